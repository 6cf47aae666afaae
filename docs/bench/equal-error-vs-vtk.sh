#!/usr/bin/env bash
# Speed at equal error against VTK (issue 40): the same camera, VTK's transfer function and
# shading, dvr and mip, five steps each, PSNR and SSIM against each renderer's own converged
# image (1/16 voxel) and against Voxray's double-precision reference, times as medians of
# alternating rounds, the table (OUT_DIR/table.md, results.tsv) and the Pareto plot
# (OUT_DIR/pareto.png). equal_error.py beside this script does the work; this script makes
# the volumes: LPS-ordered little-endian int16 HU raws in OUT_DIR/data (never in the shared
# data), read alike by VTK and by voxray-cli.
#
# usage: docs/bench/equal-error-vs-vtk.sh OUT_DIR
# env:
#   DEVICE     cpu (default) or gpu: Voxray's OpenCL device and VTK's mapper (fixed-point ray
#              caster on cpu; the GPU mapper on gpu, skipped with a note when EGL gives no GPU
#              context, i.e. Mesa's llvmpipe)
#   SCENES     comma-separated: ct400 (the 512x512x400 CT of make-ct400.sh), cthead (Stanford
#              CThead in HU, 256x256x113, 1x1x2 mm), phantom64 (a 64^3 head-like phantom, for
#              the test); default ct400,cthead
#   MODES      default dvr,mip       STEPS   default 4,2,1,0.5,0.25 (voxels)
#   PREINT_STEPS  dvr: also Voxray with --preintegrate on at these steps (voxels), its own rows
#              "Voxray preint" (default none; e.g. 1,2,4,8)
#   ADAPTIVE_IMAGE  every mode: also Voxray with --adaptive-image T,K (image-space adaptive
#              sampling), each ';'-separated setting its own rows "Voxray adaptive T,K"
#              (default none; e.g. "4,4;8,4;16,2")   ADAPTIVE_STEPS  their steps (default STEPS)
#   SIZE       default 512x384       ROUNDS  default 3      FRAMES  default 3 (per round)
#   AZIMUTH, ELEVATION, ZOOM, FOV: the camera (defaults 30, 15, 1.3, 30)
#   CLI        voxray-cli (default build/bin/voxray-cli)
#   PYTHON     a Python with vtk, scikit-image, matplotlib (default the repository's .venv,
#              made by scripts/bootstrap)
#   RAW400     the ct400 raw (ct400-raw.py) when already made; else made in OUT_DIR/data
#   SCORE      on (default); off: render and time only, no reference and no scores (the GPU
#              machine: VTK and numpy there, no scikit-image, scipy or matplotlib); again: score
#              the images an earlier SCORE=off run left in OUT_DIR, with its times (results.tsv),
#              and write the table and the plot (the same scenes, modes, steps and camera)
#   DATA       the shared data folder (default ../shared/data from the repository)
# VTK renders offscreen through EGL (VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow).
set -euo pipefail
out=${1:?usage: equal-error-vs-vtk.sh OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cli=${CLI:-$root/build/bin/voxray-cli}
py=${PYTHON:-$root/.venv/bin/python}
data=${DATA:-$root/../shared/data}
mkdir -p "$out/data"
case "$(cd "$out" && pwd)" in */shared/data*) echo "refusing to write into the shared data" >&2; exit 1 ;; esac
case ${SCORE:-on} in
  on) score=() ;;
  off) score=(--no-score) ;;
  again) score=(--rescore) ;;
  *) echo "SCORE: on, off or again, not '$SCORE'" >&2; exit 1 ;;
esac
needs="import vtkmodules, numpy"
[ "${SCORE:-on}" = off ] || needs="$needs, skimage, scipy, matplotlib"
if [ ! -x "$py" ] || ! "$py" -c "$needs" 2>/dev/null; then
  echo "$py cannot $needs: run scripts/bootstrap (or set PYTHON)" >&2
  exit 1
fi
[ -x "$cli" ] || { echo "$cli not found: build voxray-cli (or set CLI)" >&2; exit 1; }

scenes=()
IFS=, read -r -a names <<<"${SCENES:-ct400,cthead}"
for name in "${names[@]}"; do
  case $name in
    ct400)
      raw=${RAW400:-$out/data/ct400_hu_le.raw}
      if [ ! -f "$raw" ]; then
        "$here/make-ct400.sh" "$out/data" "$data/dicom/ct-visible-human-pelvis" >&2
        "$py" "$here/ct400-raw.py" "$out/data/ct400" "$raw" >&2
      fi
      scenes+=(--scene "ct400=$raw:512,512,400:1,1,1") ;;
    cthead)
      raw=$out/data/cthead_lps_hu.raw
      if [ ! -f "$raw" ]; then
        # Big-endian raw CT numbers, slice 1 the top of the head (LPI): reversed to LPS, -1024 HU.
        "$py" - "$data/stanford/CThead" "$raw" <<'EOF'
import sys
import numpy as np
src, dst = sys.argv[1], sys.argv[2]
sl = [np.fromfile(f"{src}/CThead.{i}", ">i2").reshape(256, 256) for i in range(1, 114)]
(np.stack(sl[::-1]).astype(np.int32) - 1024).astype("<i2").tofile(dst)
EOF
      fi
      scenes+=(--scene "cthead=$raw:256,256,113:1,1,2") ;;
    phantom64)
      raw=$out/data/phantom64.raw
      # A head-like phantom: a smooth skull shell (1000 HU) around soft tissue (40 HU) and a
      # denser core, in air, 64^3 voxels of 2 mm, smooth enough that a finer step converges.
      "$py" - "$raw" <<'EOF'
import sys
import numpy as np
n = 64
c = (np.arange(n) - (n - 1) / 2) / (n / 2)
z, y, x = np.meshgrid(c, c, c, indexing="ij")
r = np.sqrt((x / 0.8) ** 2 + (y / 0.9) ** 2 + (z / 0.75) ** 2)
edge = lambda d: 0.5 * (1 + np.tanh(d / 0.04))
hu = -1000 + 1040 * edge(1 - r) + 960 * edge(1 - r) * edge(r - 0.85)
hu += 600 * edge(0.25 - np.sqrt((x - 0.2) ** 2 + y ** 2 + (z + 0.1) ** 2))
np.rint(hu).astype("<i2").tofile(sys.argv[1])
EOF
      scenes+=(--scene "phantom64=$raw:64,64,64:2,2,2") ;;
    *) echo "SCENES: unknown scene '$name' (ct400, cthead, phantom64)" >&2; exit 1 ;;
  esac
done

echo "load before: $(cat /proc/loadavg)" >&2
VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow "$py" "$here/equal_error.py" --out "$out" --cli "$cli" \
  "${scenes[@]}" --modes "${MODES:-dvr,mip}" --steps "${STEPS:-4,2,1,0.5,0.25}" \
  --preint-steps "${PREINT_STEPS:-}" --adaptive-image "${ADAPTIVE_IMAGE:-}" \
  --adaptive-steps "${ADAPTIVE_STEPS:-}" --size "${SIZE:-512x384}" --rounds "${ROUNDS:-3}" --frames "${FRAMES:-3}" \
  --device "${DEVICE:-cpu}" --azimuth "${AZIMUTH:-30}" --elevation "${ELEVATION:-15}" \
  --zoom "${ZOOM:-1.3}" --fov "${FOV:-30}" "${score[@]}"
