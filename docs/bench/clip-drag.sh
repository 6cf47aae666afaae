#!/usr/bin/env bash
# Issue 41 item 3: a clip-handle drag against a rotation on the 512x512x400 CT (make-ct400.sh),
# CT-Bone dvr, a 1024x768 3D view, each replayed as the 3D view renders it (`bench --drag`:
# the drag preset sized and stepped by the frame-rate controller toward 20 fps). The clip
# drag moves the clip box's anterior face in to half the volume and back with the camera
# still (`--drag clip:N`); each replay prints the controller's settings, the frame times after
# its first change and the empty-space classifications after the first frame (0: the tables
# were not rebuilt for any move). Runs with PoCL's own CPU target and, as the AVX2 stand-in
# for the EPYC, POCL_LLVM_CPU_NAME=haswell POCL_KERNELLIB_NAME=avx2 (own kernel cache each).
#
# usage: [FRAMES=60] docs/bench/clip-drag.sh CT400_DIR   (env: CLI)
set -euo pipefail
dir=$1
here=$(cd "$(dirname "$0")" && pwd)
cli=${CLI:-$here/../../build/bin/voxray-cli}
frames=${FRAMES:-60}
cache=$(mktemp -d)
trap 'rm -rf "$cache"' EXIT
for target in native avx2; do
  for drag in "$frames" "clip:$frames"; do
    echo "== $target --drag $drag; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
    if [ $target = avx2 ]; then
      export POCL_LLVM_CPU_NAME=haswell POCL_KERNELLIB_NAME=avx2 POCL_CACHE_DIR=$cache/avx2
    else
      unset POCL_LLVM_CPU_NAME POCL_KERNELLIB_NAME
      export POCL_CACHE_DIR=$cache/native
    fi
    VOXRAY_DEVICE=cpu "$cli" bench "$dir" --mode dvr --preset CT-Bone --quality balanced \
      --sizes 1024x768 --frames 2 --warmup 1 --no-count --drag "$drag" 2>/dev/null |
      sed -n '/replay/,/^device/p'
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
