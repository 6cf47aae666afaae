#!/bin/bash
# The GPU figures of the stop of 2026-11-29 (issues 34, 35, 36, 38) on a 2-GPU machine. Build
# and carry as gpu-bench.sh says (build-gpu: lean, also -DVOXRAY_WITH_MP4=OFF; the shared
# libraries it links that the image lacks in build-gpu/lib); made here beforehand:
# build-gpu/data/pet.nii.gz (overlay-ab.sh's PET, by the venv's nibabel). Run from the root:
#   docs/bench/gpu-round6.sh small   labels, fused dvr, 2D TF (CThead, 1920x1080, on GPU 0);
#                                     multi-GPU on the 512x512x400 CT at 3840x2160, ESS off
#   docs/bench/gpu-round6.sh big     multi-GPU on a 2048x2048x1024 CT (8 GiB), 3840x2160
set -x
. docs/bench/gpu-env.sh
export CLI="$B" DATA=$D DEVICE=gpu SIZE=1920x1080 RUNS=3
heavy="--mode dvr --preset CT-Bone --sizes 3840x2160 --frames 12 --warmup 2 --ess off"
# Two GPUs: one part on each; one GPU: two parts on it (two contexts: the split's overhead).
if (($(nvidia-smi -L | wc -l) > 1)); then two="--split 2 --devices 0,1"; else two="--split 2 --device 0"; fi
split_cases() {  # INPUT...: one GPU (the raycaster), the part kernel on one GPU, two parts
  for run in 1 2; do
    $B bench "$@" $heavy --device 0 --no-count 2>&1
    $B bench "$@" $heavy --split 1 --devices 0 2>&1
    $B bench "$@" $heavy $two 2>&1
  done
}
case ${1:-small} in
  split)  # the split cases of 'small' alone
    make_ct512
    # shellcheck disable=SC2086
    split_cases $V
    ;;
  small)
    bash docs/bench/labels-ab.sh
    PET=$D/pet.nii.gz bash docs/bench/overlay-ab.sh
    bash docs/bench/tf2d-ab.sh
    make_ct512
    # shellcheck disable=SC2086
    split_cases $V
    ;;
  big)
    make_ct512
    time python3 docs/bench/make_ct_big.py /tmp/ct512.raw /tmp/ctbig.raw 4 1024
    # shellcheck disable=SC2086
    split_cases /tmp/ctbig.raw --raw-dims 2048,2048,1024 --raw-type i16 \
      --raw-spacing 0.1196,0.1196,0.1582
    ;;
esac
