#!/usr/bin/env bash
# The GPU rows of the equal-error benchmark (issue 40): VTK's GPU mapper against Voxray on the
# same GPU, equal-error-vs-vtk.sh's method, on the device machine (docs/bench/README.md,
# "GPU figures"). That machine has NVIDIA's OpenCL and EGL and a Python with numpy, but no
# VTK, scikit-image, scipy or matplotlib and no shared data; so it renders and times only
# (SCORE=off) and this machine scores the same images afterwards (SCORE=again).
#
# Carried (build/carry/, made here): eqpack.tar.xz (build-gpu's voxray-cli and its libraries,
# and eq/cthead_lps_hu.raw), vtk.aa + vtk.ab (a split xz tar of the vtkmodules the script's
# imports load, from PyPI's vtk wheel for the device's Python, stripped), pelvis150.raw.xz (the
# 150 HU slices that make-ct400.sh mirrors into the 400-slice CT), glvnd.tar.xz (Debian's
# libglvnd: the machine has NVIDIA's EGL vendor library but not the libEGL.so.1 that loads
# it). Two calls, the machine warm
# between them: `unpack` (first carry), then `run` (second carry).
#
# usage: docs/bench/gpu-equal-error.sh unpack|run      OUT: where the images and times go
#        then here: SCORE=again SCENES=... docs/bench/equal-error-vs-vtk.sh DIR_FROM_THE_DEVICE
set -euo pipefail
g=build-gpu
case ${1:?unpack or run} in
  unpack)
    mkdir -p $g
    tar xJf build/carry/eqpack.tar.xz -C $g
    cp build/carry/vtk.aa $g/vtk.aa
    echo "unpacked: $(ls $g)" ;;
  run)
    cat $g/vtk.aa build/carry/vtk.ab | tar xJf - -C $g
    tar xJf build/carry/glvnd.tar.xz -C $g
    # ct400 as make-ct400.sh makes it: slice s of 400 is slice s mod 150 of the pelvis, the
    # order reversed in every other block of 150.
    xz -dc build/carry/pelvis150.raw.xz > /tmp/pelvis150.raw
    python3 - /tmp/pelvis150.raw /tmp/ct400_hu_le.raw <<'PY'
import sys
src = open(sys.argv[1], "rb").read()
size, n = 512 * 512 * 2, 150
assert len(src) == n * size, len(src)
with open(sys.argv[2], "wb") as f:
    for s in range(400):
        block, r = divmod(s, n)
        i = n - 1 - r if block % 2 else r
        f.write(src[i * size:(i + 1) * size])
PY
    mkdir -p /tmp/vendors && echo /usr/lib/libnvidia-opencl.so.1 > /tmp/vendors/nvidia.icd
    export OCL_ICD_VENDORS=/tmp/vendors
    root=$PWD
    # The carried CLI through the carried loader when the system's does not start it.
    cat > /tmp/voxray-cli <<SH
#!/bin/sh
if [ -z "\${VX_LOADER:-}" ]; then exec $root/$g/bin/voxray-cli "\$@"; fi
exec $root/$g/lib/ld-linux-x86-64.so.2 --library-path $root/$g/lib $root/$g/bin/voxray-cli "\$@"
SH
    chmod +x /tmp/voxray-cli
    /tmp/voxray-cli devices >/dev/null 2>&1 || export VX_LOADER=1
    /tmp/voxray-cli devices
    nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader
    out=${OUT:-/tmp}/ee-gpu
    mkdir -p "$out/data"
    cp $g/eq/cthead_lps_hu.raw "$out/data/"
    LD_LIBRARY_PATH=$root/$g/glvnd PYTHONPATH=$root/$g VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow DEVICE=gpu SCORE=off \
      CLI=/tmp/voxray-cli PYTHON=$(command -v python3) RAW400=/tmp/ct400_hu_le.raw \
      SCENES=${SCENES:-ct400,cthead} MODES=${MODES:-dvr,mip} ROUNDS=${ROUNDS:-3} \
      FRAMES=${FRAMES:-3} ADAPTIVE_IMAGE=${ADAPTIVE_IMAGE:-} \
      docs/bench/equal-error-vs-vtk.sh "$out"
    rm -rf "$out/data" ;;
  *) echo "unpack or run" >&2; exit 1 ;;
esac
