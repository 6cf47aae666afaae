#!/usr/bin/env bash
# Pixels unchanged by a refactor (issue 33): the same scenes rendered by two voxray-cli
# binaries, compared file for file (PNG: no time stamp is written, so equal pixels are
# equal bytes). Scenes: every mode, gradient, lighting model (cinematic with a fixed seed),
# the quality presets, a session-free slice of each plane, a slab, an oblique slice, cine
# and orbit movie frames; on the embedded phantom, and on CThead when the shared data are
# beside the checkout.
#
# usage: docs/bench/refactor-ab.sh OLD_CLI NEW_CLI [DEVICE]   (DEVICE: cpu (default) or gpu)
# prints one line per scene ("same" or "DIFFERS") and exits 1 when any differs.
set -uo pipefail
old=$1 new=$2 device=${3:-cpu}
here=$(cd "$(dirname "$0")" && pwd)
data=${VOXRAY_DATA:-$here/../../../shared/data}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scenes=(
  "render --mode iso --gradient central"
  "render --mode iso --gradient sobel --refine 4"
  "render --mode iso --gradient zucker-hummel --projection orthographic"
  "render --mode dvr --preset CT-Bone"
  "render --mode dvr --preset CT-Bone --adaptive 0.01 --jitter on"
  "render --mode mip --window 400,40"
  "render --mode iso --lighting shadows"
  "render --mode dvr --preset CT-Bone --lighting ao"
  "render --mode dvr --preset CT-Bone --lighting cinematic --seed 7 --spp 4"
  "render --mode iso --lighting cinematic --seed 3 --spp 2 --bounces 2"
  "render --quality interactive"
  "render --quality balanced --mode dvr"
  "render --quality reference --mode iso"
  "render --mode dvr --step 0.7 --clip 0.1,0.9,0.2,0.8,0,0.6"
  "slice --plane axial"
  "slice --plane coronal"
  "slice --plane sagittal"
  "slice --normal 1,1,1"
)
movies=("--cine axial --frames 3" "--cine sagittal --frames 2" "--orbit azimuth --frames 2")
inputs=("")
if [[ -d $data/stanford/CThead ]]; then
  inputs+=("$data/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big \
--raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI")
fi
fail=0
compare() {  # NAME: old and new outputs differ?
  if [[ -s $out/old-$1 ]] && cmp -s "$out/old-$1" "$out/new-$1"; then echo "same     $2"; else
    echo "DIFFERS  $2"
    fail=1
  fi
}
n=0
for input in "${inputs[@]}"; do
  for scene in "${scenes[@]}"; do
    n=$((n + 1))
    extra=""
    [[ $scene == render* ]] && extra="--size 160x120 --device $device"
    for which in old new; do
      cli=${!which}
      # shellcheck disable=SC2086
      $cli ${scene%% *} $input ${scene#* } $extra -o "$out/$which-$n.png" >/dev/null 2>&1 ||
        echo "failed: $which $scene"
    done
    compare "$n.png" "$scene ${input%% *}"
  done
  for movie in "${movies[@]}"; do
    n=$((n + 1))
    for which in old new; do
      cli=${!which}
      # shellcheck disable=SC2086
      $cli movie $movie $input --size 96x72 --device $device -o "$out/$which-$n/" \
        >/dev/null 2>&1 || echo "failed: $which movie $movie"
    done
    if diff -rq "$out/old-$n" "$out/new-$n" >/dev/null; then echo "same     movie $movie ${input%% *}"; else
      echo "DIFFERS  movie $movie ${input%% *}"
      fail=1
    fi
  done
done
exit $fail
