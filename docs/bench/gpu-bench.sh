#!/bin/bash
# The GPU run behind gpu-h200.txt. Build here (lean: no UI, DICOM or OpenImageIO):
#   cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DVOXRAY_WITH_OIIO=OFF \
#     -DVOXRAY_WITH_DICOM=OFF -DVOXRAY_BUILD_UI=OFF -DVOXRAY_BUILD_TESTS=OFF \
#     -DVOXRAY_BUILD_BENCH=OFF "-DCMAKE_EXE_LINKER_FLAGS=-static-libstdc++ -static-libgcc"
#   ninja -C build-gpu; copy the shared data the script names into build-gpu/data;
# carry build-gpu/bin and build-gpu/data to the GPU machine and run this script there
# from the repository root.
set -x
mkdir -p /tmp/vendors && echo /usr/lib/libnvidia-opencl.so.1 > /tmp/vendors/nvidia.icd
export OCL_ICD_VENDORS=/tmp/vendors
ldd --version | head -1
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
B="build-gpu/bin/voxray-cli"
if ! $B devices >/dev/null 2>&1; then
  B="build-gpu/lib/ld-linux-x86-64.so.2 --library-path build-gpu/lib build-gpu/bin/voxray-cli"
fi
$B devices
D=build-gpu/data
CT="$D/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big --raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI"
$B bench --seed-table --data $D --device gpu --frames 36 --sizes 512x384,640x480,800x600,1024x768,1920x1080 2>&1
for m in iso dvr mip; do $B bench $CT --device gpu --sizes 1920x1080 --gradients central,zucker-hummel --kernel both --mode $m --frames 36 2>&1; done
python3 docs/bench/make_ct512.py $D/raw/cranium-ct/cranium_256x256x108_s16le.raw /tmp/ct512.raw
V="/tmp/ct512.raw --raw-dims 512,512,400 --raw-type i16 --raw-spacing 0.4785,0.4785,0.405"
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --kernel both 2>&1
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --ess off 2>&1
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --storage buffer 2>&1
# Sampling throughput on heavy frames (per-frame overhead amortised): dvr with every sample
# taken (no ESS, no early termination) against mip without ESS (trilinear + max: the
# plainest sampling loop, a stand-in for the raw trilinear limit).
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 4096x4096 --frames 12 --ess off --early-termination 1 2>&1
$B bench $V --device gpu --mode mip --sizes 4096x4096 --frames 12 --ess off 2>&1
$B bench $V --device gpu --mode iso --iso 300 --sizes 4096x4096 --frames 12 --ess off 2>&1
