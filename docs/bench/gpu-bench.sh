#!/bin/bash
# The GPU run behind gpu-h200.txt. Build here (lean: no UI, DICOM or OpenImageIO):
#   cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DVOXRAY_WITH_OIIO=OFF \
#     -DVOXRAY_WITH_DICOM=OFF -DVOXRAY_BUILD_UI=OFF -DVOXRAY_BUILD_TESTS=OFF \
#     -DVOXRAY_BUILD_BENCH=OFF "-DCMAKE_EXE_LINKER_FLAGS=-static-libstdc++ -static-libgcc"
#   ninja -C build-gpu; copy the shared data the script names into build-gpu/data;
# carry build-gpu/bin and build-gpu/data to the GPU machine and run this script there
# from the repository root.
set -x
. docs/bench/gpu-env.sh
$B bench --seed-table --data $D --device gpu --frames 36 --sizes 512x384,640x480,800x600,1024x768,1920x1080 2>&1
for m in iso dvr mip; do $B bench $CT --device gpu --sizes 1920x1080 --gradients central,zucker-hummel --kernel both --mode $m --frames 36 2>&1; done
make_ct512
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --kernel both 2>&1
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --ess off 2>&1
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 1920x1080 --frames 36 --storage buffer 2>&1
# Sampling throughput on heavy frames (per-frame overhead amortised): dvr with every sample
# taken (no ESS, no early termination) against mip without ESS (trilinear + max: the
# plainest sampling loop, a stand-in for the raw trilinear limit).
$B bench $V --device gpu --mode dvr --preset CT-Bone --sizes 4096x4096 --frames 12 --ess off --early-termination 1 2>&1
$B bench $V --device gpu --mode mip --sizes 4096x4096 --frames 12 --ess off 2>&1
$B bench $V --device gpu --mode iso --iso 300 --sizes 4096x4096 --frames 12 --ess off 2>&1
