#!/usr/bin/env bash
# Writes a 512x512x400 CT DICOM series for the format and movie benchmarks (issue 13) into
# OUT_DIR/ct400/. The shared data has no 400-slice series, so this stacks the real Visible
# Human pelvis CT (../shared/data/dicom/ct-visible-human-pelvis, 150 slices of 512x512, 1 mm)
# with its mirror: slices 0-149 are the pelvis bottom to top, 150-299 the same slices top to
# bottom, 300-399 the first 100 again, so the anatomy runs on without a jump. Positions
# continue 1 mm apart from the pelvis' own first z; each slice gets its own SOP instance UID
# and all share one new series UID. Pixels and every other header field are the pelvis' own.
# Needs DCMTK's command-line tools (Debian: dcmtk). Never writes into the shared data.
#
# usage: docs/bench/make-ct400.sh OUT_DIR [PELVIS_DIR]
set -euo pipefail
out=${1:?usage: make-ct400.sh OUT_DIR [PELVIS_DIR]}
src=${2:-$(dirname "$0")/../../../shared/data/dicom/ct-visible-human-pelvis}
mkdir -p "$out/ct400"
dest=$(cd "$out/ct400" && pwd)
case "$dest" in */shared/data*) echo "refusing to write into the shared data: $dest" >&2; exit 1 ;; esac

# The pelvis' files sorted by slice position (their names are not in slice order).
mapfile -t sorted < <(for f in "$src"/*.dcm; do
  z=$(dcmdump +P 0020,0032 "$f" | tr -d '\000' | sed -E 's/.*\[([^]]*)\].*/\1/' | cut -d'\' -f3)
  printf '%s %s\n' "$z" "$f"
done | sort -g | cut -d' ' -f2-)
n=${#sorted[@]}
first=$(dcmdump +P 0020,0032 "${sorted[0]}" | tr -d '\000' | sed -E 's/.*\[([^]]*)\].*/\1/')
x0=$(cut -d'\' -f1 <<<"$first")
y0=$(cut -d'\' -f2 <<<"$first")
z0=$(cut -d'\' -f3 <<<"$first")
root=1.2.826.0.1.3680043.10.1082.400
for ((s = 0; s < 400; s++)); do
  block=$((s / n)) r=$((s % n))
  if ((block % 2 == 1)); then i=$((n - 1 - r)); else i=$r; fi
  z=$(awk -v a="$z0" -v b="$s" 'BEGIN { print a + b }')
  f=$(printf '%s/ct400.%04d.dcm' "$dest" "$s")
  cp "${sorted[$i]}" "$f"
  dcmodify -nb -q -m "(0020,0032)=$x0\\$y0\\$z" -m "(0020,0013)=$((s + 1))" \
    -m "(0008,0018)=$root.1.$((s + 1))" -m "(0020,000e)=$root.2" -i "(0020,1041)=$z" "$f"
done
echo "$dest: 400 slices of 512x512, 1 mm apart from z = $z0 mm"
