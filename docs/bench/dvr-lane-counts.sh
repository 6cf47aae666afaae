#!/usr/bin/env bash
# Where a dvr packet's lane slots go (issue 16), counted by instrumented copies of the kernels
# (experiments/dvr-lane-counts.patch, made on kernels/march_lanes.cl before it was split, applied
# to its dvr part kernels/march/dvr_packet.cl, one copy per count, VOXRAY_KERNEL_DIR): the
# bench's sample counter then adds the chosen count instead of the samples. One view (the
# orbit's first frame), VTK's table, the ct400-raw.py raw, millions per frame:
#   1 slots       lanes with a ray, times iterations times DVR_BATCH
#   2 live        samples taken (slots minus lanes whose ray has ended)
#   3 seen        live samples with opacity > 0
#   4 empty       transparent samples in empty macro cells (waiting for the packet to leap)
#   5 empty early the part of 4 before the lane's own check index
#   6 fine empty  transparent samples in occupied macro cells whose 2^3-voxel sub-cell (with
#                 its apron, voxels 2c-1 .. 2c+2) looks up transparent at its max (exact for
#                 a table whose opacity rises with the value, as VTK's does)
#   7 bound, per-lane leaps   per packet, the most samples one lane takes outside empty
#                             cells, times the packet's lanes with a ray
#   8 bound, + 2^3 sub-cells  the same, also without the samples of 6
# usage: docs/bench/dvr-lane-counts.sh LANES [SIZE] (env RAW, CLI, POCL_CACHE_DIR; COUNTS, e.g.
#   "1 2": only those; QUALITY, e.g. balanced: the workstation's case instead, CT-Bone on the
#   DICOM series DICOM (default /work/ct/ct400) with that preset, SIZE being the view's size)
set -euo pipefail
lanes=$1 size=${2:-512x384}
here=$(cd "$(dirname "$0")" && pwd)
raw=${RAW:-/tmp/ct400_hu_le.raw}
cli=${CLI:-$here/../../build/bin/voxray-cli}
tf=-1000:0:0:0:0,-100:0.72:0.45:0.36:0,0:0.8:0.5:0.4:0.0143,40:0.82:0.55:0.45:0.02,400:1:1:0.9:0.9,3000:1:1:1:1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
input=("$raw" --raw-dims "512,512" --raw-type i16 --raw-spacing "1,1,1" --tf "$tf")
[ -n "${QUALITY:-}" ] && input=("${DICOM:-/work/ct/ct400}" --preset CT-Bone --quality "$QUALITY")
names=(- slots live seen empty "empty early" "fine empty" "bound, per-lane leaps" "bound, + 2^3 sub-cells")
for n in ${COUNTS:-1 2 3 4 5 6 7 8}; do
  cp -r "$here/../../kernels" "$work/k$n"
  sed 's|kernels/march_lanes.cl|kernels/march/dvr_packet.cl|' \
    "$here/experiments/dvr-lane-counts.patch" | patch -s -d "$work/k$n" -p2
  sed -i "1i #define CNT $n" "$work/k$n/march/dvr_packet.cl"
  orbit=(--orbit elevation --zoom 1.37)
  [ -n "${QUALITY:-}" ] && orbit=()
  VOXRAY_KERNEL_DIR=$work/k$n "$cli" bench "${input[@]}" --mode dvr "${orbit[@]}" --sizes "$size" \
    --frames 1 --lanes "$lanes" --json 2>/dev/null |
    python3 -c 'import json,sys; d=json.load(sys.stdin)[0]; print("%.2f" % (d["samples_per_s"]*d["median_ms"]*1e-9))' |
    sed "s/^/lanes $lanes $size ${names[$n]}: /; s/$/ M/"
done
