#!/bin/bash
# The GPU figures of the stop of 2026-11-29 evening (issue 38 part 1). Build and carry as
# gpu-round6.sh says, with the CLI before the change as build-gpu/bin/voxray-cli-before and
# GNU time as build-gpu/bin/time (the image has none). Run from the root:
#   docs/bench/gpu-round8.sh first   first-image.sh on the 2048x2048x1024 CT (8 GiB,
#                                    make_ct_big.py): the CLI before (render only) and now
#                                    (render, --first-image with coarse factors 1, 4, 8)
set -x
. docs/bench/gpu-env.sh
export TIME_BIN=build-gpu/bin/time
case ${1:-first} in
  first)
    make_ct512
    time python3 docs/bench/make_ct_big.py /tmp/ct512.raw /tmp/ctbig.raw 4 1024
    free -g | head -2
    BEFORE=${B/voxray-cli/voxray-cli-before}
    # Before: render only (it has no --first-image); twice, from the page cache.
    for run in 1 2; do
      # shellcheck disable=SC2086
      $TIME_BIN -f %e_s_wall_%M_KiB_peak_RSS $BEFORE render /tmp/ctbig.raw \
        --raw-dims 2048,2048,1024 --raw-type i16 --raw-rescale 1,0 --mode dvr \
        --preset CT-Bone --device gpu --size 1920x1080 -o /tmp/before.png 2>&1
    done
    bash docs/bench/first-image.sh /tmp/ctbig.raw 2048,2048,1024 "$B"
    ;;
esac
