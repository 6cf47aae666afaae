#!/bin/bash
# Issue 38's CPU goal: "with the process limited to 3 GiB, an 8 GiB OME-Zarr opens, shows a
# first image within 2 s and converges" (and the 8 GiB raw file read on demand, host memory
# <= 1.1x the volume). The 2048x2048x1024 int16 CT (8 GiB) from make_ct_big.py (as
# gpu-mpi.sh's make_big), converted with voxray-cli convert (its peak RSS reported), then
# voxray-cli bench --memory-budget on PoCL under a 3 GiB address-space limit (prlimit --as:
# this container has no systemd and a cgroup v1 hierarchy the helpers must not touch).
# bench prints the time to the first image (a preview from the coarse level), to the first
# converged frame, the medians and the peak RSS. The files go under DIR and are deleted.
# FIRST=1: bench --first-image, the first image alone (context, opening, frame; no converged
# frame), as run G in out-of-core-pocl.txt timed it.
#
#   docs/bench/out-of-core-3g.sh [DIR] [CLI]    (defaults /tmp/zarr38-data, build/bin/voxray-cli)
set -u
DIR=${1:-/tmp/zarr38-data}
B=${2:-build/bin/voxray-cli}
RAW=$DIR/ctbig.raw
Z=$DIR/ctbig.ome.zarr
IN="$RAW --raw-dims 2048,2048,1024 --raw-type i16 --raw-spacing 0.1196,0.1196,0.1582"
LOOK="--mode dvr --preset CT-Bone --device cpu --sizes ${SIZE:-512x512} --frames ${FRAMES:-1}"
[ "${FIRST:-0}" = 1 ] && LOOK="$LOOK --first-image"
BUDGET=${BUDGET:-1280}
PARTS=${PARTS:-32}
LIMIT=${LIMIT:-3221225472}  # 3 GiB of address space
TIME="/usr/bin/time -f %e_s_wall_%M_KiB_peak_RSS"
mkdir -p "$DIR"
if [ ! -f "$RAW" ]; then
  python3 docs/bench/make_ct512.py "$DIR/ct512.raw" &&
    python3 docs/bench/make_ct_big.py "$DIR/ct512.raw" "$RAW" 4 1024 || exit 1
fi
nproc; free -g | head -2; cat /proc/loadavg
if [ ! -d "$Z" ]; then
  echo "== convert (the raw file read and written a chunk's depth of slices at a time, never whole)"
  # shellcheck disable=SC2086
  $TIME "$B" convert $IN -o "$Z"
  cat /proc/loadavg
fi
echo "== OME-Zarr streamed, budget $BUDGET MiB, parts of $PARTS slices, prlimit --as=$LIMIT"
# shellcheck disable=SC2086
$TIME prlimit --as="$LIMIT" "$B" bench "$Z" $LOOK --memory-budget "$BUDGET" --part-slices "$PARTS"
cat /proc/loadavg
echo "== raw file read with pread, budget $BUDGET MiB, parts of $PARTS slices, prlimit --as=$LIMIT"
# shellcheck disable=SC2086
$TIME prlimit --as="$LIMIT" "$B" bench $IN $LOOK --memory-budget "$BUDGET" --part-slices "$PARTS"
cat /proc/loadavg
[ "${KEEP:-0}" = 1 ] || rm -rf "$RAW" "$Z" "$DIR/ct512.raw"
