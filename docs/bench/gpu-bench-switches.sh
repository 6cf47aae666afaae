#!/bin/bash
# Issue 17 on the GPU: the kernels built from the switch list (this build, build-gpu/bin)
# against those of 39d4ec0, before it (its lean build copied to build-gpu/base): the same
# images, and the same speed in the same run.
# Build both as gpu-bench.sh says; carry build-gpu/bin, build-gpu/base and
# build-gpu/data/stanford/CThead; run from the repository root. Output: gpu-switches.txt.
. docs/bench/gpu-env.sh
A=build-gpu/base/voxray-cli
set -x
# Pixels: this lean build writes no images, so the accuracy sweep stands in for them: its
# errors against the double-precision reference (MAE, PSNR, hit-point distances, to 16
# digits) are functions of every pixel and hit, and must come out the same.
$A accuracy --device gpu --scenes sphere64-iso,torus64-iso/r,ml64-dvr,ml64-mip/r --json >/tmp/before.json 2>/dev/null
$B accuracy --device gpu --scenes sphere64-iso,torus64-iso/r,ml64-dvr,ml64-mip/r --json >/tmp/after.json 2>/dev/null
python3 - <<'PY'
import json
a, b = json.load(open("/tmp/before.json")), json.load(open("/tmp/after.json"))
strip = lambda r: {k: v for k, v in r.items() if k not in ("ms_per_frame", "samples_per_s", "setting")}
same = len(a) == len(b) and all(strip(x) == strip(y) for x, y in zip(a, b))
print(f"accuracy rows: {len(a)} before, {len(b)} after; every error figure the same: {same}")
for x, y in zip(a, b):
    if strip(x) != strip(y): print("differs:", x["setting"], "|", y["setting"])
PY
# Speed: before, after, before, after; specialised and uber kernels.
for m in iso dvr mip; do
  for bin in $A "$B" $A "$B"; do
    $bin bench $CT --device gpu --mode $m --sizes 1920x1080 --frames 36 --kernel both --no-count 2>&1
  done
done
