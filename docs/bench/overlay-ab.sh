#!/bin/bash
# Fused dvr (issue 36) on PoCL: CThead, CT-Bone dvr at 512x384, a 12-frame orbit per run,
# alone and with a synthetic PET overlay (NIfTI, 66 x 66 x 131 voxels of 4 mm on its own grid,
# a background of 1 and six spheres of 8, radius 15 mm; hot-iron over the window 2 ... 10,
# opacity 0.5); 6 runs of the two cases alternating, so that load changes hit both alike.
# Results: docs/bench/overlay-pocl.txt. Run from the checkout's root with build/bin/voxray-cli
# built and the venv (nibabel) linked at .venv.
set -euo pipefail
# DEVICE=gpu SIZE=1920x1080 RUNS=3: the same cases on a GPU (docs/bench/gpu-round6.sh).
DEVICE=${DEVICE:-cpu}
SIZE=${SIZE:-512x384}
RUNS=${RUNS:-6}
CLI=${CLI:-build/bin/voxray-cli}
PY=${PY:-.venv/bin/python}
DATA=${DATA:-../shared/data}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
CT="$DATA/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big --raw-spacing 1,1,2
    --raw-rescale 1,-1024 --raw-axes LPI"
# PET=FILE: that overlay (made here beforehand) where the venv is missing (the GPU machines).
if [[ -n ${PET:-} ]]; then
  cp "$PET" "$WORK/pet.nii.gz"
else
  "$PY" - "$WORK/pet.nii.gz" <<'PY'
import sys
import nibabel as nib
import numpy as np
# LPS: origin (-20, -20, -262) mm, 4 mm voxels along L, P, S (wider than CThead's box
# whichever way its slices run); NIfTI stores RAS, so x and y flip sign.
n = (66, 66, 131)
lps0 = np.array([-20.0, -20.0, -262.0])
i, j, k = np.meshgrid(*[np.arange(d) for d in n], indexing="ij")
p = np.stack([lps0[0] + 4 * i, lps0[1] + 4 * j, lps0[2] + 4 * k], axis=-1)
vol = np.ones(n, dtype=np.float32)
for c in [(80, 90, 60), (170, 120, 110), (120, 180, 170), (80, 90, -60), (170, 120, -110),
          (120, 180, -170)]:
    vol[np.linalg.norm(p - np.array(c, dtype=float), axis=-1) <= 15.0] = 8.0
aff = np.diag([-4.0, -4.0, 4.0, 1.0])
aff[:3, 3] = [-lps0[0], -lps0[1], lps0[2]]
nib.save(nib.Nifti1Image((vol * 100).astype(np.int16), aff), sys.argv[1])
PY
fi
common="--mode dvr --preset CT-Bone --sizes $SIZE --frames 12 --warmup 2 --no-count --csv"
for run in $(seq "$RUNS"); do
  for c in alone fused; do
    case $c in
      alone) extra="" ;;
      fused) extra="--overlay $WORK/pet.nii.gz --overlay-window 200,1000 --overlay-opacity 0.5" ;;
    esac
    echo "run $run case $c load $(cut -d' ' -f1-3 /proc/loadavg)"
    # shellcheck disable=SC2086
    VOXRAY_DEVICE=$DEVICE $CLI bench $CT $common $extra 2>/dev/null | grep '^CThead'
  done
done
