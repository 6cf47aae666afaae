#!/usr/bin/env bash
# The workstation's case on the 512x512x400 CT (issue 16): CT-Bone on the DICOM series of
# make-ct400.sh, the 3D view 1024x768, Voxray's own orbit, each frame as the 3D view plans
# it (`bench --quality`, resources/quality/*.json): `balanced` = the sharp frame, 1024x768 at
# 1.5-voxel steps, 6 bisections; `interactive` = a drag frame, half size (512x384), 2-voxel
# steps, 4 bisections; both with the presets' Zucker-Hummel gradient. Prints the bench's
# wall median and the kernel's user CPU time per frame (perf cpu-clock:u, 2 ms samples in
# PoCL's raycast.so, difference of 2- and 6-frame runs), which holds steadier than wall time
# on a shared machine; on 2 idle cores a frame would take at best about half its CPU time.
# STALL=N: then N replays of the end of a drag per lane width (bench --stall): the largest
# gap between frames shown with the sharp frame whole (the old scheduler) and in bands.
# DRAG=N: then a drag of N frames per lane width as the 3D view renders it (bench --drag:
# the drag preset sized and stepped by the GUI's frame-rate controller, 20 fps): each
# setting it chose and the frame times after its first change.
#
# usage: [STALL=N] [DRAG=N] docs/bench/ct400-workstation.sh CT400_DIR LANES...   (env: CLI, POCL_CACHE_DIR)
set -euo pipefail
dir=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
cli=${CLI:-$here/../../build/bin/voxray-cli}
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for l in "$@"; do
  for q in balanced interactive; do
    declare -A c
    for f in 2 6; do
      perf record -q -e cpu-clock:u -c 2000000 -o "$data/p" -- "$cli" bench "$dir" --mode dvr --preset CT-Bone \
        --quality $q --sizes 1024x768 --frames $f --no-count --lanes "$l" 2>/dev/null |
        awk -v q=$q -v l="$l" '/ pack / {print "  " q, "lanes", l, $2, "wall median ms", $6}'
      c[$f]=$(perf script -i "$data/p" -F ip,dso 2>/dev/null | grep -c raycast.so)
    done
    echo "$q lanes $l kernel cpu ms/frame $(((c[6] - c[2]) * 2 / 4))"
  done
  if [ "${STALL:-0}" -gt 0 ]; then
    "$cli" bench "$dir" --mode dvr --preset CT-Bone --quality balanced --sizes 1024x768 --frames 2 \
      --warmup 1 --no-count --lanes "$l" --stall "$STALL" 2>/dev/null | sed -n '/stall replay/,/^device/p' | grep -v '^device'
  fi
  if [ "${DRAG:-0}" -gt 0 ]; then
    "$cli" bench "$dir" --mode dvr --preset CT-Bone --quality balanced --sizes 1024x768 --frames 2 \
      --warmup 1 --no-count --lanes "$l" --drag "$DRAG" 2>/dev/null | sed -n '/drag replay/,/^device/p' | grep -v '^device'
  fi
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
