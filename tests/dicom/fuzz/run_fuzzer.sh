#!/usr/bin/env bash
# Builds a seed corpus from the shared DICOM files (small ones, under /tmp, never in the
# repository) and runs the fuzzer. Usage: run_fuzzer.sh FUZZER [SECONDS]
set -euo pipefail
fuzzer=$1
seconds=${2:-600}
data=$(cd "$(dirname "$0")/../../../../shared/data/dicom" && pwd)
corpus=/tmp/voxray-dicom-corpus
mkdir -p "$corpus"
# Named by content hash: IM-0001-0001-0001.dcm exists in many folders.
find "$data" -type f -size -300k ! -name LICENSE | while read -r f; do
  cp -n "$f" "$corpus/$(sha1sum "$f" | cut -c1-16)"
done
exec "$fuzzer" "$corpus" -max_total_time="$seconds" -max_len=300000 -timeout=20 \
  -rss_limit_mb=4096 -print_final_stats=1
