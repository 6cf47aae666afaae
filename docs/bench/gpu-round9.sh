#!/bin/bash
# The GPU figures of issue 38 item 4's goal (two GPUs: the 2048x2048x1024 CT >= 1.6x the one-GPU
# frame rate at 4K with --ess off), after the composite moved onto the first device
# (MultiDeviceOptions::Composite, --composite device|host). Build the lean CLI (gpu-bench.sh:
# build-gpu, -DVOXRAY_BUILD_UI=OFF, no DICOM/OIIO/MP4, static libstdc++), put the shared
# libraries it links and the loader into build-gpu/lib and the carried cranium into
# build-gpu/data (gpu-env.sh takes the loader when the CLI does not start as it is). Run from
# the root:
#   docs/bench/gpu-round9.sh two   one GPU (the Raycaster) against two parts on two GPUs with
#                                  the composite on the first device (also with --balance) and
#                                  on the host, and the part kernel alone on one GPU (--split
#                                  1), at 3840x2160, dvr CT-Bone, ESS off: the 8 GiB CT first,
#                                  then the 512x512x400 (docs/bench/gpu-h200x2-round9.txt)
#   docs/bench/gpu-round9.sh bands  the 8 GiB CT at 4K, ESS off, after the banded kernels went
#                                  onto two queues: one GPU, then two GPUs with the device
#                                  composite over 1, 2, 4 and 8 bands, without and with --balance,
#                                  and the part kernel alone on one GPU over 1 and 8 bands
set -x
. docs/bench/gpu-env.sh
nproc
cat /proc/loadavg
nvidia-smi topo -m
heavy="--mode dvr --preset CT-Bone --sizes 3840x2160 --frames 12 --warmup 2 --ess off"
# Two GPUs: one part on each; one GPU: two parts on it (two contexts: the split's overhead).
if (($(nvidia-smi -L | wc -l) > 1)); then two="--split 2 --devices 0,1"; else two="--split 2 --device 0"; fi
cases() {  # INPUT...: the one-GPU frame, two GPUs (device, host composite), the part kernel alone
  # shellcheck disable=SC2086
  for run in 1 2; do
    time $B bench "$@" $heavy --device 0 --no-count 2>&1
    time $B bench "$@" $heavy $two --composite device 2>&1
    time $B bench "$@" $heavy $two --composite device --balance 2>&1
    time $B bench "$@" $heavy $two --composite host 2>&1
    [[ $run == 1 ]] && time $B bench "$@" $heavy --split 1 --devices 0 --composite device 2>&1
    cat /proc/loadavg
  done
}
big="/tmp/ctbig.raw --raw-dims 2048,2048,1024 --raw-type i16 --raw-spacing 0.1196,0.1196,0.1582"
case ${1:-two} in
  alternate)  # the goal's ratio round by round: one GPU, then two (4 bands, with and without
    # --balance), ROUNDS times, so each ratio is taken from frames minutes apart at most
    make_ct512
    time python3 docs/bench/make_ct_big.py /tmp/ct512.raw /tmp/ctbig.raw 4 1024
    # shellcheck disable=SC2086
    for ((run = 1; run <= ${ROUNDS:-4}; run++)); do
      $B bench $big $heavy --device 0 --no-count 2>&1
      $B bench $big $heavy $two --composite device --bands 4 2>&1
      $B bench $big $heavy $two --composite device --bands 4 --balance 2>&1
    done ;;
  bands)
    make_ct512
    time python3 docs/bench/make_ct_big.py /tmp/ct512.raw /tmp/ctbig.raw 4 1024
    # shellcheck disable=SC2086
    for run in 1 2; do
      $B bench $big $heavy --device 0 --no-count 2>&1
      for bands in 1 2 4 8; do
        $B bench $big $heavy $two --composite device --bands $bands 2>&1
        $B bench $big $heavy $two --composite device --bands $bands --balance 2>&1
      done
      [[ $run == 1 ]] && for bands in 1 8; do
        $B bench $big $heavy --split 1 --devices 0 --composite device --bands $bands 2>&1
      done
      cat /proc/loadavg
    done
    ;;
  two)
    make_ct512
    time python3 docs/bench/make_ct_big.py /tmp/ct512.raw /tmp/ctbig.raw 4 1024
    cases /tmp/ctbig.raw --raw-dims 2048,2048,1024 --raw-type i16 \
      --raw-spacing 0.1196,0.1196,0.1582
    # shellcheck disable=SC2086
    cases $V
    ;;
esac
