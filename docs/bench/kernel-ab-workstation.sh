#!/usr/bin/env bash
# Kernel directories against each other on the workstation's frame (issue 16): CT-Bone on the
# DICOM series of make-ct400.sh, `bench --quality Q --sizes 1024x768` (the 3D view's frame, as
# ct400-workstation.sh), one voxray-cli binary, the kernels read from each directory
# (VOXRAY_KERNEL_DIR), alternating in every round. CPU ms per frame of PoCL's raycast.so
# (perf cpu-clock:u, the 6-frame run minus the 2-frame run), as kernel-ab-cpu.sh.
#
# usage: docs/bench/kernel-ab-workstation.sh ROUNDS LANES QUALITY DIR...
#   e.g. docs/bench/kernel-ab-workstation.sh 3 8,16 balanced /tmp/main/kernels kernels
# env: CT (the series, default /work/ct/ct400), CLI (voxray-cli), POCL_CACHE_DIR
set -euo pipefail
rounds=$1 lanes=$2 quality=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
ct=${CT:-/work/ct/ct400}
cli=${CLI:-$here/../../build/bin/voxray-cli}
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
run() {  # DIR LANES FRAMES: ms of raycast.so CPU time
  perf record -q -e cpu-clock:u -c 2000000 -o "$data/p" -- env VOXRAY_KERNEL_DIR="$1" \
    "$cli" bench "$ct" --mode dvr --preset CT-Bone --quality "$quality" --sizes 1024x768 \
    --frames "$3" --no-count --lanes "$2" >/dev/null 2>&1
  echo $(($(perf script -i "$data/p" -F ip,dso 2>/dev/null | grep -c raycast.so) * 2))
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq "$rounds"); do
  for l in ${lanes//,/ }; do
    for dir in "$@"; do
      a=$(run "$dir" "$l" 2)
      b=$(run "$dir" "$l" 6)
      echo "round $r $quality lanes $l $dir cpu ms/frame $(((b - a) / 4))"
    done
  done
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
