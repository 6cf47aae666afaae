#!/bin/bash
# The GPU stability certificate (issue 16): the stability suite, the shading extremes and the
# kernel-vs-reference cases of voxray_engine_tests, run on an NVIDIA GPU through NVIDIA's
# OpenCL driver (kernels built with -cl-fast-relaxed-math), in every mode and in both volume
# storages (buffer and image3d_t), then the CLI's accuracy sweep on the GPU. Each case
# renders twice and requires the same bytes, and agrees with the double-precision reference
# within the tolerance PoCL is held to (tests/engine/stability_helpers.h). The log of the run
# is docs/stability/gpu-stability-h100.txt (or -h200).
#
# Build here (lean: no UI, DICOM, formats, OpenImageIO or FFmpeg; engine tests only):
#   cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DVOXRAY_WITH_OIIO=OFF \
#     -DVOXRAY_WITH_DICOM=OFF -DVOXRAY_WITH_FORMATS=OFF -DVOXRAY_WITH_MP4=OFF \
#     -DVOXRAY_BUILD_UI=OFF -DVOXRAY_BUILD_TESTS=ON -DVOXRAY_TEST_AREAS=engine \
#     -DVOXRAY_BUILD_BENCH=OFF "-DCMAKE_EXE_LINKER_FLAGS=-static-libstdc++ -static-libgcc"
#   ninja -C build-gpu
# carry build-gpu/bin (and build-gpu/lib: this machine's loader, libc, libm, libz, for an
# image with an older glibc) and run this script from the repository root there.
set -u -o pipefail
. docs/bench/gpu-env.sh
T=build-gpu/bin/voxray_engine_tests
if ! $T --gtest_list_tests >/dev/null 2>&1; then
  T="build-gpu/lib/ld-linux-x86-64.so.2 --library-path build-gpu/lib $T"
fi
# The shared data is not on the GPU machine: the CThead cases skip themselves.
cases='Stability*:Shading*:*KernelVsReference*:*EmptySpace*:Slabs*:*/Slabs*:Lighting*:MonteCarlo*:Path*'
status=0
for storages in buffer image; do
  echo "=== VOXRAY_TEST_DEVICE=gpu VOXRAY_TEST_STORAGES=$storages"
  VOXRAY_TEST_DEVICE=gpu VOXRAY_TEST_STORAGES=$storages $T --gtest_filter="$cases" \
    --gtest_brief=1 2>&1 | grep -v '^\[       OK \]' || status=1
done
echo "=== accuracy sweep on the GPU (analytic scenes against the double reference)"
$B accuracy --device gpu --frames 3 --quiet 2>&1 || status=1
echo "=== exit $status"
exit $status
