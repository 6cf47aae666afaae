#!/usr/bin/env bash
# Whole-process WADO-RS retrieve-then-open of a CT series against curl (issue 39 item 8): what
# the user waits for, from exec to exit, with Orthanc (Debian's orthanc + orthanc-dicomweb) on
# loopback started here as the PACS tests' fixture starts it (tests/pacs/orthanc_server.cpp:
# its own configuration, free ports, a temporary store, basic authentication).
# Each round runs, in turns (the first step of a round rotates, and each starts after sync):
#   curl     curl of the series' WADO-RS multipart into one file (what any client transfers)
#   whole    voxray-cli pacs get NODE --study --series --json into a fresh cache: retrieve and
#            open into a volume (the volume's info is the output: the "ready volume" step)
#   retrieve voxray-cli pacs get ... --no-open: retrieve into the cache only
#   before   (only with BEFORE=path/to/another/voxray-cli) the whole step with that binary
# and prints the medians (wall and CPU seconds) and their ratios to curl, with /proc/loadavg.
#
# usage: docs/bench/wado-whole-process.sh [ROUNDS [SERIES_FOLDER]]
#   ROUNDS: default 5. SERIES_FOLDER: a folder of one DICOM series; default the 512x512x400
#   CT that docs/bench/make-ct400.sh writes, made under WORK (default /tmp/voxray-wado-bench)
#   when it is not there yet. VOXRAY_CLI: the binary (default build/bin/voxray-cli).
#   STEPS: the steps to run (default "curl whole retrieve"; curl first).
# Needs curl, time (/usr/bin/time), dcmtk, python3, orthanc and orthanc-dicomweb
# (scripts/bootstrap). Writes only under WORK; never into the shared data.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
rounds=${1:-5}
work=${WORK:-/tmp/voxray-wado-bench}
cli=${VOXRAY_CLI:-$root/build/bin/voxray-cli}
before=${BEFORE:-}
mkdir -p "$work"
series=${2:-$work/ct400}
if [[ -z ${2:-} && ! -d $series ]]; then "$here/make-ct400.sh" "$work" >&2; fi
[[ -x $cli ]] || { echo "no voxray-cli at $cli: build it (target voxray-cli)" >&2; exit 1; }

# The fixture's server: free ports, its own store, loopback only, the test user.
user=voxray password=bench-secret
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
run=$(mktemp -d "$work/run-XXXXXX")
http=$(free_port) dicom=$(free_port)
cat >"$run/orthanc.json" <<EOF
{"Name": "voxray-bench", "StorageDirectory": "$run/storage", "IndexDirectory": "$run/storage",
 "HttpPort": $http, "DicomPort": $dicom, "DicomAet": "ORTHANC", "RemoteAccessAllowed": false,
 "AuthenticationEnabled": true, "RegisteredUsers": {"$user": "$password"}, "SaveJobs": false,
 "StableAge": 1, "Plugins": ["/usr/share/orthanc/plugins/libOrthancDicomWeb.so"],
 "DicomWeb": {"Enable": true, "Root": "/dicom-web/"}}
EOF
/usr/sbin/Orthanc --no-jobs "$run/orthanc.json" >"$run/orthanc.log" 2>&1 &
orthanc=$!
trap 'kill $orthanc 2>/dev/null; wait $orthanc 2>/dev/null; rm -rf "$run"' EXIT
base=http://127.0.0.1:$http
for ((i = 0; i < 300; i++)); do
  curl -sf -u "$user:$password" "$base/system" >/dev/null && break
  sleep 0.1
done
curl -sf -u "$user:$password" "$base/system" >/dev/null || { cat "$run/orthanc.log" >&2; exit 1; }

# Upload (POST /instances, 4 at a time) and the UIDs from the files themselves.
mapfile -t files < <(find "$series" -type f -name '*.dcm' | sort)
printf '%s\n' "${files[@]}" | xargs -P 4 -I{} curl -sf -u "$user:$password" -X POST \
  --data-binary @{} "$base/instances" -o /dev/null
tag() { dcmdump +P "$1" "${files[0]}" | tr -d '\000' | sed -E 's/.*\[([^]]*)\].*/\1/'; }
study=$(tag 0020,000d) seriesUid=$(tag 0020,000e)
stored=$(curl -sf -u "$user:$password" "$base/statistics" |
  python3 -c 'import json,sys; print(json.load(sys.stdin)["CountInstances"])')
[[ $stored == "${#files[@]}" ]] || { echo "Orthanc stored $stored of ${#files[@]}" >&2; exit 1; }

# The node, as a user configures it (the CLI takes no password in a URL).
mkdir -p "$run/config/voxray"
printf '{"nodes": {"bench": {"url": "%s/dicom-web", "user": "%s", "password": "%s"}}}\n' \
  "$base" "$user" "$password" >"$run/config/voxray/pacs-nodes.json"
export XDG_CONFIG_HOME=$run/config

url="$base/dicom-web/studies/$study/series/$seriesUid"
accept='multipart/related; type="application/dicom"; transfer-syntax=*'
# The command of each step, in CMD.
command_of() {
  local get=(pacs get bench --study "$study" --series "$seriesUid" --cache "$run/cache" --json)
  case $1 in
    curl) cmd=(curl -sf -u "$user:$password" -H "Accept: $accept" "$url" -o "$run/curl.out") ;;
    whole) cmd=("$cli" "${get[@]}") ;;
    retrieve) cmd=("$cli" "${get[@]}" --no-open) ;;
    before) cmd=("$before" "${get[@]}") ;;
  esac
}
cleanup() { rm -rf "$run/cache" "$run/curl.out"; }

read -ra steps <<<"${STEPS:-curl whole retrieve}"  # curl first: the ratios are to it
[[ -n $before ]] && steps+=(before)
declare -A wall cpu
echo "series $series: ${#files[@]} files, $(du -sm "$series" | cut -f1) MB; $rounds rounds"
echo "voxray-cli $cli${before:+; before: $before}"
echo "load average at the start: $(cat /proc/loadavg)"
for ((r = 0; r < rounds; r++)); do
  n=${#steps[@]}
  for ((k = 0; k < n; k++)); do
    s=${steps[$(((k + r) % n))]}
    cleanup
    sync
    # /usr/bin/time: wall (%e) and the process's own CPU seconds (%U + %S).
    command_of "$s"
    /usr/bin/time -f '%e %U %S' -o "$run/time" "${cmd[@]}" >"$run/out" ||
      { echo "step $s failed: ${cmd[*]}" >&2; exit 1; }
    read -r e u sy <"$run/time"
    wall[$s]+="$e "
    cpu[$s]+="$(awk -v a="$u" -v b="$sy" 'BEGIN { printf "%.2f", a + b }') "
    if [[ $s == curl ]]; then bytes=$(stat -c %s "$run/curl.out"); fi
  done
  echo "round $((r + 1)): load $(cut -d' ' -f1-3 /proc/loadavg)"
done
cleanup
median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END {
  print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
printf '%-10s %9s %9s   %s\n' step "wall s" "CPU s" "runs (wall s)"
for s in "${steps[@]}"; do
  printf '%-10s %9.3f %9.2f   %s\n' "$s" "$(median <<<"${wall[$s]}")" \
    "$(median <<<"${cpu[$s]}")" "${wall[$s]}"
done
c=$(median <<<"${wall[curl]}")
for s in "${steps[@]:1}"; do
  printf '%-10s / curl: %.2fx\n' "$s" "$(awk -v a="$(median <<<"${wall[$s]}")" -v b="$c" \
    'BEGIN { print a / b }')"
done
echo "curl transferred $((bytes / 1000000)) MB; load average at the end: $(cat /proc/loadavg)"
