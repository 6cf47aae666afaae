#!/bin/bash
# Label-aware dvr (issue 34) on PoCL: CThead, CT-Bone dvr at 512x384, a 12-frame orbit per
# run, without labels and with a synthetic segment (label 1: a sphere of radius 50 mm around
# the volume's centre) coloured (mask off), shown (show:1) and hidden (hide:1); 6 runs of
# the four cases alternating, so that load changes hit all alike. Results:
# docs/bench/labels-pocl.txt. Run from the checkout's root with build/bin/voxray-cli built.
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
python3 - "$WORK/sphere.raw" <<'PY'
import sys
nx, ny, nz, sz = 256, 256, 113, 2.0
c = ((nx - 1) / 2, (ny - 1) / 2, (nz - 1) / 2)
out = bytearray(nx * ny * nz)
for z in range(nz):
    for y in range(ny):
        for x in range(nx):
            if (x - c[0]) ** 2 + (y - c[1]) ** 2 + ((z - c[2]) * sz) ** 2 <= 50.0 ** 2:
                out[(z * ny + y) * nx + x] = 1
open(sys.argv[1], "wb").write(out)
PY
common="--mode dvr --preset CT-Bone --sizes $SIZE --frames 12 --warmup 2 --no-count --csv"
for run in $(seq "$RUNS"); do
  for c in none colours show hide; do
    case $c in
      none) extra="" ;;
      colours) extra="--labels-raw $WORK/sphere.raw" ;;
      show) extra="--labels-raw $WORK/sphere.raw --segment-mask show:1" ;;
      hide) extra="--labels-raw $WORK/sphere.raw --segment-mask hide:1" ;;
    esac
    echo "run $run case $c load $(cut -d' ' -f1-3 /proc/loadavg)"
    # shellcheck disable=SC2086
    VOXRAY_DEVICE=$DEVICE $CLI bench $CT $common $extra 2>/dev/null | grep '^CThead'
  done
done
