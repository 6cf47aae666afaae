#!/usr/bin/env bash
# VTK's vtkFixedPointVolumeRayCastMapper against Voxray's packets on the 512x512x400 CT (issue 16),
# same voxels (ct400-raw.py), same orbit (VTK's: bench --orbit elevation --zoom 1.37), VTK's
# transfer function for dvr (history/sessions-01-04.md, "Against VTK's CPU ray caster"), 2 threads each.
# Two measures per case:
#  - wall: rounds of VTK then Voxray, medians of ms per frame (this machine's speed drifts:
#    compare only within a round);
#  - cpu: the renderer's user CPU time per frame from perf (cpu-clock:u, one sample per 2 ms),
#    the difference between runs of 2 and 8 frames so that one-off work cancels (VTK's normal
#    encoding, PoCL's kernel builds, the macro cells). VTK = libvtkRenderingVolume + libm (its
#    ray casting threads), Voxray = the raycast kernel (PoCL's raycast.so). On a machine shared
#    with other work this holds steadier than wall time (about +-3 % between repeats).
#
# usage: docs/bench/ct400-vs-vtk.sh wall|cpu ROUNDS SIZES MODES LANES...
#   e.g. docs/bench/ct400-vs-vtk.sh cpu 1 512x384 dvr,mip 16 8
# env: RAW (the ct400-raw.py file), CLI (voxray-cli), VTK_PY (the venv's python),
#      PEERS (../shared/peers), POCL_CACHE_DIR, FRAMES (cpu: the longer run's frames, default 8;
#      iso's frames are short, about 15-20 samples each at 2 ms: 32 frames hold the count's
#      noise near 5 %), VOXRAY_ARGS (more bench flags for Voxray, e.g. "--adaptive 0.1"; split
#      at spaces)
# An AVX2 build on an AVX-512 machine (the kernels PoCL makes for an AVX2-only CPU, here run
# on this one's cores): POCL_LLVM_CPU_NAME=haswell POCL_KERNELLIB_NAME=avx2 with a
# POCL_CACHE_DIR of its own, and LANES 8 (history/sessions-12-14.md, Session 12).
set -euo pipefail
how=$1 rounds=$2 sizes=$3 modes=$4
long=${FRAMES:-8}
shift 4
here=$(cd "$(dirname "$0")" && pwd)
raw=${RAW:-/tmp/ct400_hu_le.raw}
cli=${CLI:-$here/../../build/bin/voxray-cli}
vtkpy=${VTK_PY:-/work/vtkenv/bin/python}
peers=${PEERS:-$here/../../../shared/peers}
tf=-1000:0:0:0:0,-100:0.72:0.45:0.36:0,0:0.8:0.5:0.4:0.0143,40:0.82:0.55:0.45:0.02,400:1:1:0.9:0.9,3000:1:1:1:1
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT

vtk() {  # MODE SIZE FRAMES (after a perf prefix, if any)
  local mode=$1 size=$2 f=$3
  shift 3
  VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow "$@" "$vtkpy" "$peers/vtk_volume_bench.py" "$raw" 512 512 400 \
    --sz 1 --mapper fixed --threads 2 --iso 400 --mode "$mode" --size "$size" --frames "$f" 2>/dev/null
}
voxray() {  # LANES MODE SIZE FRAMES (after a perf prefix, if any)
  local l=$1 mode=$2 size=$3 f=$4
  shift 4
  local extra=()
  [ "$mode" = dvr ] && extra=(--tf "$tf")
  [ "$mode" = iso ] && extra=(--iso 400)
  "$@" "$cli" bench "$raw" --raw-dims 512,512 --raw-type i16 --raw-spacing 1,1,1 --mode "$mode" \
    "${extra[@]}" ${VOXRAY_ARGS:-} --orbit elevation --zoom 1.37 --sizes "$size" --frames "$f" --no-count --lanes "$l" |
    grep ' pack '
}
cpu_ms() {  # PATTERN: ms of user CPU in the matching objects
  echo $(($(perf script -i "$data/p" -F ip,dso 2>/dev/null | grep -c -E "$1") * 2))
}

for r in $(seq "$rounds"); do
  for size in ${sizes//,/ }; do
    for mode in ${modes//,/ }; do
      vmode=$mode
      [ "$mode" = dvr ] && vmode=composite
      if [ "$how" = wall ]; then
        f=12
        [ "$size" = 1024x768 ] && f=8
        vtk "$vmode" "$size" $f env | sed "s/^/round $r VTK /" || true
        for l in "$@"; do voxray "$l" "$mode" "$size" $f | sed "s/^/round $r lanes $l /"; done
      else
        rec=(perf record -q -e cpu-clock:u -c 2000000 -o "$data/p" --)
        vtk "$vmode" "$size" 2 "${rec[@]}" >/dev/null
        a=$(cpu_ms 'libvtkRenderingVolume|libm.so')
        vtk "$vmode" "$size" "$long" "${rec[@]}" >/dev/null
        b=$(cpu_ms 'libvtkRenderingVolume|libm.so')
        echo "round $r $mode $size VTK cpu ms/frame $(((b - a) / (long - 2)))"
        for l in "$@"; do
          voxray "$l" "$mode" "$size" 2 "${rec[@]}" >/dev/null
          a=$(cpu_ms raycast.so)
          voxray "$l" "$mode" "$size" "$long" "${rec[@]}" >/dev/null
          b=$(cpu_ms raycast.so)
          echo "round $r $mode $size Voxray lanes $l cpu ms/frame $(((b - a) / (long - 2)))"
        done
      fi
    done
  done
done
