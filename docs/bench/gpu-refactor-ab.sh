#!/bin/bash
# Issue 33 on a GPU: a refactor leaves pixels and speed unchanged. Two lean CLIs (before in
# build-gpu/old, after in build-gpu/bin; built as gpu-bench.sh says) on the same GPU in one
# run: every error figure of the accuracy sweep (mae, rmse, psnr, ssim, surface and normal
# errors against the double-precision reference, to 17 digits) must be equal, which they
# are only if the pixels are; then frame times, old and new alternating, medians.
set -x
. docs/bench/gpu-env.sh
OLD="${B/build-gpu\/bin/build-gpu/old}"
scenes=ml64-iso,ml64-dvr,ml64-mip,sphere64-iso,torus64-dvr,ramp64-mip
strip() {  # the figures without times, rates and variant names
  python3 -c 'import json,sys
for r in json.load(sys.stdin):
    for k in ("ms_per_frame","samples_per_s","setting"): r.pop(k, None)
    print(json.dumps(r, sort_keys=True))'
}
for which in OLD B; do
  ${!which} accuracy --scenes $scenes --synthetic-size 320x240 --frames 1 --device gpu --json \
    --quiet 2>/dev/null | strip >/tmp/acc-$which.txt
  ${!which} accuracy $CT --scenes none --size 640x480 --mode dvr --preset CT-Bone --frames 1 \
    --device gpu --json --quiet 2>/dev/null | strip >>/tmp/acc-$which.txt
done
wc -l /tmp/acc-OLD.txt /tmp/acc-B.txt
if cmp /tmp/acc-OLD.txt /tmp/acc-B.txt; then echo "ACCURACY FIGURES IDENTICAL"; else
  echo "ACCURACY FIGURES DIFFER"; diff /tmp/acc-OLD.txt /tmp/acc-B.txt | head -20; fi
for round in 1 2 3; do
  for which in OLD B; do
    for m in iso dvr mip; do
      echo "round $round $which $m"
      ${!which} bench $CT --device gpu --sizes 1920x1080 --mode $m --frames 36 2>&1 | grep -A1 median_ms | tail -1
    done
    ${!which} bench $CT --device gpu --sizes 1280x720 --mode dvr --lighting cinematic --frames 8 2>&1 | grep -A1 median_ms | tail -1
  done
done
