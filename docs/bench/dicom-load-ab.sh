#!/bin/bash
# A/B of the DICOM folder import: voxray_dicom_load_once binaries taking turns (order
# rotated each round), ROUNDS rounds; per binary the medians of the import's own seconds
# (printed by the tool, process start and exit excluded), the process's wall seconds and its
# CPU seconds (user + sys, /usr/bin/time). The machine is shared: CPU time is the steadier.
# Usage: docs/bench/dicom-load-ab.sh ROUNDS INPUT NAME=BINARY [NAME=BINARY ...]
set -eu
rounds=$1 input=$2
shift 2
out=$(mktemp) tf=$(mktemp)
trap 'rm -f "$out" "$tf"' EXIT
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 0; r < rounds; r++)); do
  n=$#
  for ((i = 0; i < n; i++)); do
    spec=${@:$(((i + r) % n + 1)):1}
    name=${spec%%=*} bin=${spec#*=}
    s=$(/usr/bin/time -o "$tf" -f "%e %U %S" "$bin" "$input" | cut -d' ' -f1)
    echo "$name $s $(cat "$tf")" >>"$out"
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-10s %10s %10s %10s  (medians of %d)\n' binary import_s wall_s cpu_s "$rounds"
for spec in "$@"; do
  name=${spec%%=*}
  awk -v n="$name" '$1 == n { print $2, $3, $4 + $5 }' "$out" | python3 -c '
import sys, statistics as st
rows = [list(map(float, l.split())) for l in sys.stdin]
print("%-10s %10.3f %10.3f %10.3f" % (sys.argv[1], *(st.median(c) for c in zip(*rows))))
' "$name"
done
