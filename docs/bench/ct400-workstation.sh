#!/usr/bin/env bash
# The workstation's case on the 512x512x400 CT (issue 16): CT-Bone on the DICOM series of
# make-ct400.sh, the 3D view 1024x768, Voxray's own orbit; `balanced` = 1024x768 at 1.5 mm
# steps (1.5 voxels), Zucker-Hummel, 6 bisections; `interactive` (a drag frame) = half
# resolution, 512x384, 2 mm steps, 4 bisections (resources/quality/*.json). Prints the bench's
# wall median and the kernel's user CPU time per frame (perf cpu-clock:u, 2 ms samples in
# PoCL's raycast.so, difference of 2- and 6-frame runs), which holds steadier than wall time
# on a shared machine; on 2 idle cores a frame would take at best about half its CPU time.
#
# usage: docs/bench/ct400-workstation.sh CT400_DIR LANES...   (env: CLI, POCL_CACHE_DIR)
set -euo pipefail
dir=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
cli=${CLI:-$here/../../build/bin/voxray-cli}
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
for l in "$@"; do
  for q in balanced interactive; do
    if [ $q = balanced ]; then a=(--step 1.5 --refine 6 --sizes 1024x768); else a=(--step 2 --refine 4 --sizes 512x384); fi
    declare -A c
    for f in 2 6; do
      perf record -q -e cpu-clock:u -c 2000000 -o "$data/p" -- "$cli" bench "$dir" --mode dvr --preset CT-Bone \
        --gradients zucker-hummel "${a[@]}" --frames $f --no-count --lanes "$l" 2>/dev/null |
        awk -v q=$q -v l="$l" '/ pack / {print "  " q, "lanes", l, "wall median ms", $6}'
      c[$f]=$(perf script -i "$data/p" -F ip,dso 2>/dev/null | grep -c raycast.so)
    done
    echo "$q lanes $l kernel cpu ms/frame $(((c[6] - c[2]) * 2 / 4))"
  done
done
