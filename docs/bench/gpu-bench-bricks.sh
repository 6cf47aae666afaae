#!/bin/bash
# Output: gpu-h200-bricks.txt. Build and carry as gpu-bench.sh says.
# Session 3 GPU run: the merged z-slab bricking and mip changes on NVIDIA, the dvr goal,
# and the seed table at 1024x768 / 1920x1080.
set -x
. docs/bench/gpu-env.sh
make_ct512
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --kernel both 2>&1
for m in dvr mip iso; do
  $B bench $V --device gpu --mode $m --preset CT-Bone --iso 300 --sizes 1920x1080 --frames 36 2>&1
  $B bench $V --device gpu --mode $m --preset CT-Bone --iso 300 --sizes 1920x1080 --frames 36 --slab-mib 64 2>&1
done
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --slab-mib 64 --storage buffer 2>&1
for m in iso dvr mip; do $B bench $CT --device gpu --sizes 1920x1080 --mode $m --orbit elevation --frames 36 2>&1; done
$B bench --seed-table --data $D --device gpu --frames 24 --sizes 1024x768,1920x1080 2>&1
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 4096x4096 --frames 12 --ess off --early-termination 1 2>&1
$B bench $V --device gpu --mode mip --sizes 4096x4096 --frames 12 --ess off 2>&1
