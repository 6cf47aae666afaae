#!/bin/bash
# Output: gpu-h200-bricks.txt. Build and carry as gpu-bench.sh says.
# Session 3 GPU run: the merged z-slab bricking and mip changes on NVIDIA, the dvr goal,
# and the seed table at 1024x768 / 1920x1080.
set -x
mkdir -p /tmp/vendors && echo /usr/lib/libnvidia-opencl.so.1 > /tmp/vendors/nvidia.icd
export OCL_ICD_VENDORS=/tmp/vendors
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
B="build-gpu/bin/voxray-cli"
if ! $B devices >/dev/null 2>&1; then
  B="build-gpu/lib/ld-linux-x86-64.so.2 --library-path build-gpu/lib build-gpu/bin/voxray-cli"
fi
$B devices
D=build-gpu/data
CT="$D/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big --raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI"
python3 docs/bench/make_ct512.py $D/raw/cranium-ct/cranium_256x256x108_s16le.raw /tmp/ct512.raw
V="/tmp/ct512.raw --raw-dims 512,512,400 --raw-type i16 --raw-spacing 0.4785,0.4785,0.405"
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
