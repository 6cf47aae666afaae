#!/bin/bash
# Issue 38 part 2 on the GPU machine: a volume larger than the device budget, out of core on
# one device (voxray-cli bench --memory-budget): preview frames over an orbit (what a drag
# shows: the parts held at full resolution, the rest from the coarse level, nothing uploaded),
# converged frames (every part, the missing ones uploaded), parts held, bytes uploaded per
# converged frame, the time to the first image, peak host memory; and the same volume in core
# for comparison when it fits. voxray-cli only: the lean build (-DVOXRAY_BUILD_UI=OFF, no DICOM
# needed) has everything this runs; its render writes no PNG, so only bench is timed.
#
#   docs/bench/out-of-core.sh [X,Y,Z] [BUDGET_MIB] [SIZE] [CLI]
#
# Defaults: 2048,2048,768 int16 (6 GiB) with a 2048 MiB budget at 1920x1080. The raw file is
# made by docs/bench/make_ball_raw.py under /tmp when missing. CLI: the voxray-cli to run
# (default: build-gpu/bin/voxray-cli through gpu-env.sh). VOXRAY_DEVICE picks the device (gpu).
# ZARR=1 also converts the raw volume to an OME-Zarr (chunks 64, blosc-zstd) and streams it.
# UPLOADS: the upload paths the out-of-core case runs, in turn (--ooc-upload, ",off" adds
# --ooc-reuse off; default "pinned pinned,off direct": the pinned staging ring with copies beside
# the kernels into evicted parts' device memory, the same allocating per part, then the blocking
# copies from pageable memory it replaced); each prints read, upload, kernel and overlapped ms per
# converged frame. On the device machine (issue 38's upload-bound frame, gpu-h200-out-of-core.txt):
# build build-gpu lean here as gpu-bench.sh's header says (voxray-cli is all it needs), carry
# build-gpu (its bin/, lib/ and the GNU time binary gpu-round8.sh names) and run from the
# repository root, 8 frames as that log (about 3 minutes: two out-of-core runs and in core):
#   TIME_BIN=build-gpu/bin/time FRAMES=8 docs/bench/out-of-core.sh 2048,2048,768 2048 1920x1080
set -u
DIMS=${1:-2048,2048,768}
BUDGET=${2:-2048}
SIZE=${3:-1920x1080}
if [ -n "${4:-}" ]; then B=$4; else . docs/bench/gpu-env.sh; fi
RAW=/tmp/ooc-${DIMS//,/x}.raw
if [ ! -f "$RAW" ]; then
  python3 docs/bench/make_ball_raw.py ${DIMS//,/ } "$RAW" || exit 1
fi
IN="$RAW --raw-dims $DIMS --raw-type i16 --raw-rescale 1,0"
LOOK="--mode dvr --preset CT-Bone --device ${VOXRAY_DEVICE:-gpu} --sizes $SIZE --frames ${FRAMES:-12}"
TIME="${TIME_BIN:-/usr/bin/time} -f %e_s_wall_%M_KiB_peak_RSS"
ls -l "$RAW"; nproc; free -g | head -2; cat /proc/loadavg
for U in ${UPLOADS:-pinned pinned,off direct}; do
  R=on
  [[ $U == *,* ]] && R=${U#*,} && U=${U%,*}
  echo "== out of core: budget $BUDGET MiB, --ooc-upload $U --ooc-reuse $R"
  $TIME $B bench $IN $LOOK --memory-budget "$BUDGET" --ooc-upload "$U" --ooc-reuse "$R" 2>&1
  cat /proc/loadavg
done
echo "== in core (the whole volume on the device; fails where it does not fit)"
$TIME $B bench $IN $LOOK --no-count 2>&1
cat /proc/loadavg
if [ "${ZARR:-0}" = 1 ]; then
  Z=/tmp/ooc-${DIMS//,/x}.ome.zarr
  [ -d "$Z" ] || $TIME $B convert $IN -o "$Z" --chunk 64 2>&1
  echo "== out of core from OME-Zarr, read on demand: budget $BUDGET MiB"
  $TIME $B bench "$Z" $LOOK --memory-budget "$BUDGET" 2>&1
  cat /proc/loadavg
fi
