#!/bin/bash
# The 2D transfer function (issue 35) on PoCL: CThead, dvr at 512x384 and the default step
# (half the smallest spacing), a 12-frame orbit per run, three cases alternating over 6 runs
# so that load changes hit them alike:
#   1d       CT-Bone as a Voxray JSON file (tf convert preset:CT-Bone), the 1D table;
#   2d-same  that file with a tf2d section that is CT-Bone again: 43 rectangles over every
#            |gradient| whose colour and opacity are CT-Bone's in their middle (20 HU wide on the
#            opacity ramp -16 ... 641 HU, 243 HU above it), so the frame shows what the 1D
#            one shows and the difference is what the 2D path costs per sample;
#   2d-edges that file with a tf2d section that keeps bone boundaries (a triangle over
#            150 ... 2000 HU at |gradient| 100 ... 1500 HU/mm) and fades bone's inside.
# Results: docs/bench/tf2d-pocl.txt. Run from the checkout's root with build/bin/voxray-cli.
set -euo pipefail
# DEVICE=gpu SIZE=1920x1080 RUNS=3: the same cases on a GPU (docs/bench/gpu-round6.sh).
DEVICE=${DEVICE:-cpu}
SIZE=${SIZE:-512x384}
RUNS=${RUNS:-6}
CLI=${CLI:-build/bin/voxray-cli}
DATA=${DATA:-../shared/data}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
CT="$DATA/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big --raw-spacing 1,1,2
    --raw-rescale 1,-1024 --raw-axes LPI"
$CLI tf convert preset:CT-Bone "$WORK/1d.json" --force > /dev/null
add_tf2d() {  # FILE PRIMITIVES-JSON ("same": CT-Bone's table as rectangles)
  python3 - "$WORK/1d.json" "$1" "$2" <<'PY'
import json, sys
tf = json.load(open(sys.argv[1]))
def interp(x, xs, ys):  # linear, constant beyond the ends (the table's rule)
    if x <= xs[0]:
        return ys[0]
    for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return ys[-1]
if sys.argv[3] == "same":
    hu = [c[0] for c in tf["color"]]
    def at(x):
        rgb = [interp(x, hu, [c[k] for c in tf["color"]]) for k in (1, 2, 3)]
        a = interp(x, [o[0] for o in tf["opacity"]], [o[1] for o in tf["opacity"]])
        return rgb, a
    edges = list(range(-16, 641, 20)) + [641 + 243 * k for k in range(11)]
    prims = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        rgb, a = at(0.5 * (lo + hi))
        prims.append({"shape": "rect", "hu": [float(lo), float(hi)], "gradient": [0, 1500],
                      "color": rgb, "opacity": a})
else:
    prims = json.loads(sys.argv[3])
tf["tf2d"] = {"version": 1, "gradientMax": 1500, "primitives": prims}
json.dump(tf, open(sys.argv[2], "w"))
PY
}
add_tf2d "$WORK/2d-same.json" same
add_tf2d "$WORK/2d-edges.json" '[{"shape": "tri", "hu": [150, 2000], "gradient": [100, 1500],
  "color": [0.9, 0.85, 0.75], "opacity": 0.6, "soft": 0.3}]'
common="--mode dvr --sizes $SIZE --frames 12 --warmup 2 --no-count --csv"
echo "device: $(VOXRAY_DEVICE=$DEVICE $CLI devices 2>/dev/null | grep -i pthread | head -1)"
for run in $(seq "$RUNS"); do
  for c in 1d 2d-same 2d-edges; do
    echo "run $run case $c load $(cut -d' ' -f1-3 /proc/loadavg)"
    # shellcheck disable=SC2086
    VOXRAY_DEVICE=$DEVICE $CLI bench $CT $common --tf-file "$WORK/$c.json" 2>/dev/null | grep '^CThead'
  done
done
