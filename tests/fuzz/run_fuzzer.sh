#!/usr/bin/env bash
# Runs one fuzz target for SECONDS, starting from its kept corpus (tests/fuzz/corpus/NAME)
# and, for the DICOM targets, the small shared DICOM files as seeds. New finds stay in a
# scratch copy under /tmp unless --keep is given: then they are merged (minimised) into
# the kept corpus, to be committed, so the next run starts where this one stopped.
# Usage: run_fuzzer.sh BUILD_DIR NAME SECONDS [--keep]   NAME: dicom|info_json|raw|params|multipart|dicomweb_json|volume_file|session|transfer_function|zarr_metadata
set -euo pipefail
build=$1
name=$2
seconds=${3:-600}
keep=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
fuzzer=$build/bin/voxray_${name}_fuzzer
kept=$here/corpus/$name
work=$(mktemp -d "/tmp/voxray-fuzz-$name.XXXXXX")
seeds=$(mktemp -d "/tmp/voxray-fuzz-seeds.XXXXXX")
trap 'rm -rf "$work" "$seeds"' EXIT
mkdir -p "$kept"
cp -r "$kept/." "$work/"
# The suppressions of the ASan test run: driver internals, and DCMTK's leak when it throws.
export LSAN_OPTIONS=suppressions=$here/../sanitizers/lsan.supp:print_suppressions=0
args=(-max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1)
case $name in
  dicom | info_json)
    data=$(cd "$here/../../../shared/data/dicom" && pwd)
    # Named by content hash: IM-0001-0001-0001.dcm exists in many folders.
    find "$data" -type f -size -300k ! -name LICENSE | while read -r f; do
      cp -n "$f" "$seeds/$(sha1sum "$f" | cut -c1-16)"
    done
    # Small inputs: headers, structure and text are what breaks; 32 KiB still holds a
    # whole compressed test image.
    args+=(-max_len=$([[ $name == dicom ]] && echo 32768 || echo 16384) -dict="$here/dicom.dict")
    ;;
  raw) args+=(-max_len=4096) ;;
  params) args+=(-max_len=1024 -dict="$here/render_params.dict") ;;
  multipart) args+=(-max_len=4096) ;;
  dicomweb_json) args+=(-max_len=4096) ;;
  volume_file) args+=(-max_len=4096) ;;
  session) args+=(-max_len=16384 -dict="$here/session.dict") ;;
  transfer_function) args+=(-max_len=8192) ;;
  # A group's and an array's metadata (about 1 KiB each as writers make them) and a small chunk.
  zarr_metadata) args+=(-max_len=8192 -dict="$here/zarr.dict") ;;
  *)
    echo "run_fuzzer.sh: unknown target '$name' (dicom, info_json, raw, params, multipart, dicomweb_json, volume_file, session, transfer_function, zarr_metadata)" >&2
    exit 2
    ;;
esac
"$fuzzer" "${args[@]}" "$work" "$seeds"
if [[ $keep == --keep ]]; then
  "$fuzzer" -merge=1 "${args[@]:1}" "$kept" "$work" "$seeds"
  # Shared files stay out of the repository (every run adds them as seeds): libFuzzer names
  # a unit by its SHA-1, so an exact copy of a seed is found by name.
  for f in "$seeds"/*; do
    [[ -e $f ]] && rm -f "$kept/$(sha1sum "$f" | cut -c1-40)"
  done
  echo "kept corpus $kept: $(find "$kept" -type f | wc -l) inputs, $(du -sh "$kept" | cut -f1)"
fi
