#!/bin/bash
# The GPU figures of the stop of 2026-11-29 afternoon (issues 35, 38). Build and carry as
# gpu-round6.sh says. Run from the root:
#   docs/bench/gpu-round7.sh tfdrag  the transfer-function edit's update cost on GPU 0
#                                    (bench --tf-drag: still and moved-table frame pairs) on
#                                    the 512x512x400 CT, dvr CT-Bone, 1024x768 and 1920x1080
#   docs/bench/gpu-round7.sh two     gpu-round6.sh's split and big cases (two GPUs when the
#                                    machine has them)
#   docs/bench/gpu-round7.sh shadowdrag  issue 40 item 4: a drag with shadows against phong
#                                    (bench --drag --lighting shadows: the light grid held
#                                    through the drag, each frame again in phong, the ratio
#                                    and the held grid's PSNR) on the 512x512x400 CT and
#                                    CThead, dvr CT-Bone balanced, 1024x768 and 1920x1080
set -x
. docs/bench/gpu-env.sh
case ${1:-tfdrag} in
  tfdrag)
    make_ct512
    for run in 1 2 3; do
      # shellcheck disable=SC2086
      $B bench $V --mode dvr --preset CT-Bone --sizes 1024x768,1920x1080 --frames 4 --warmup 2 \
        --device 0 --no-count --tf-drag 40 2>&1
    done
    ;;
  shadowdrag)
    make_ct512
    for run in 1 2; do
      for input in "$V" "$CT"; do
        # shellcheck disable=SC2086
        $B bench $input --mode dvr --preset CT-Bone --quality balanced \
          --sizes 1024x768,1920x1080 --frames 4 --warmup 2 --device 0 --no-count \
          --lighting shadows --drag 60 2>&1
      done
    done
    ;;
  two)
    bash docs/bench/gpu-round6.sh split
    bash docs/bench/gpu-round6.sh big
    ;;
esac
