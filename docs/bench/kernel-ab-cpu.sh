#!/usr/bin/env bash
# Kernel directories against each other on the 512x512x400 CT (issue 16): one voxray-cli
# binary, the kernels read from each directory (VOXRAY_KERNEL_DIR), alternating in every
# round. CPU ms per frame of PoCL's raycast.so as in ct400-vs-vtk.sh (perf cpu-clock:u, the
# 8-frame run minus the 2-frame run, so kernel builds and one-off work cancel).
#
# usage: docs/bench/kernel-ab-cpu.sh ROUNDS SIZE MODE LANES DIR...
#   e.g. docs/bench/kernel-ab-cpu.sh 3 512x384 mip 16,8 /tmp/main/kernels kernels
# env: RAW (ct400-raw.py's file), CLI (voxray-cli), FRAMES (the longer run, default 8),
#      VOXRAY_ARGS (more bench flags), POCL_CACHE_DIR
set -euo pipefail
rounds=$1 size=$2 mode=$3 lanes=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
raw=${RAW:-/tmp/ct400_hu_le.raw}
cli=${CLI:-$here/../../build/bin/voxray-cli}
long=${FRAMES:-8}
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
run() {  # DIR LANES FRAMES: ms of raycast.so CPU time
  perf record -q -e cpu-clock:u -c 2000000 -o "$data/p" -- env VOXRAY_KERNEL_DIR="$1" \
    "$cli" bench "$raw" --raw-dims 512,512 --raw-type i16 --raw-spacing 1,1,1 --mode "$mode" \
    ${VOXRAY_ARGS:-} --orbit elevation --zoom 1.37 --sizes "$size" --frames "$3" --no-count \
    --lanes "$2" >/dev/null 2>&1
  echo $(($(perf script -i "$data/p" -F ip,dso 2>/dev/null | grep -c raycast.so) * 2))
}
for r in $(seq "$rounds"); do
  for l in ${lanes//,/ }; do
    for dir in "$@"; do
      a=$(run "$dir" "$l" 2)
      b=$(run "$dir" "$l" "$long")
      echo "round $r $mode $size lanes $l $dir cpu ms/frame $(((b - a) / (long - 2)))"
    done
  done
done
