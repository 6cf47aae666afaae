#!/usr/bin/env bash
# Issue 40 item 4: shadows during a drag against phong, as the 3D view renders a drag
# (`bench --drag`: the drag preset sized and stepped by the frame-rate controller toward
# 20 fps) with the light following the camera (the default). The replay holds the light
# grid through the drag as the workstation does (Raycaster::holdLightGrid) and renders each
# drag frame in phong right after it (the same setting, the same load): it prints the grid's
# builds after the first frame (0: held), the lit / phong ratio frame by frame (goal <= 1.3),
# and the held grid's PSNR against the frame rebuilt for its own light 10, 30, 60 and 90
# degrees into the drag (beside phong's: no shadows at all). CT-Bone dvr, balanced, a
# 1024x768 view, on the 512x512x400 CT (make-ct400.sh) and CThead.
#
# usage: [FRAMES=60] [DEVICE=cpu] docs/bench/shadow-drag.sh CT400_DIR [CTHEAD_DIR]  (env: CLI)
# The GPU run: docs/bench/gpu-round7.sh shadowdrag.
set -euo pipefail
ct400=$1
here=$(cd "$(dirname "$0")" && pwd)
cthead=${2:-$here/../../../shared/data/stanford/CThead}
cli=${CLI:-$here/../../build/bin/voxray-cli}
frames=${FRAMES:-60}
raw="--raw-dims 256,256 --raw-type i16 --raw-endian big --raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI"
for input in "$ct400" "$cthead $raw"; do
  echo "== $input; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  # shellcheck disable=SC2086
  VOXRAY_DEVICE=${DEVICE:-cpu} "$cli" bench $input --mode dvr --preset CT-Bone \
    --quality balanced --sizes 1024x768 --frames 2 --warmup 1 --no-count --lighting shadows \
    --drag "$frames" 2>/dev/null | sed -n '/^input/,/^memory/p'
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
