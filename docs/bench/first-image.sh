#!/bin/bash
# Issue 38 part 1 on the GPU machine: the time to the first image (a 4x or 8x coarse level's
# frame) and to the full-resolution frame of a large raw volume, split by step (read, coarse
# level, upload, empty-space tables, frames), and the process's peak host memory against the
# volume's bytes. voxray-cli only (the lean GPU build: no Qt, DICOM or OpenImageIO).
#
#   docs/bench/first-image.sh RAW X,Y,Z [CLI]
#
# RAW: little-endian int16 voxels in HU (made by docs/bench/make_ball_raw.py when missing:
# e.g. 1024,1024,1024 is 2 GiB, 2048,2048,1024 8 GiB). CLI: the voxray-cli to run (default:
# build-gpu/bin/voxray-cli, through gpu-env.sh's vendors file and carried loader).
# The "today" lines run `bench --frames 1` under /usr/bin/time, which any voxray-cli has: run
# them with main's CLI for the figures before this change.
set -u
RAW=${1:?usage: first-image.sh RAW X,Y,Z [CLI]}
DIMS=${2:?usage: first-image.sh RAW X,Y,Z [CLI]}
if [ -n "${3:-}" ]; then B=$3; else . docs/bench/gpu-env.sh; fi
if [ ! -f "$RAW" ]; then
  python3 docs/bench/make_ball_raw.py ${DIMS//,/ } "$RAW" || exit 1
fi
IN="$RAW --raw-dims $DIMS --raw-type i16 --raw-rescale 1,0"
FRAME="--mode dvr --preset CT-Bone --sizes 1920x1080 --device ${VOXRAY_DEVICE:-gpu}"
TIME="/usr/bin/time -f %e_s_wall_%M_KiB_peak_RSS"
ls -l "$RAW"; nproc; free -g | head -2; cat /proc/loadavg
for run in 1 2; do  # the first run reads the file from disk, the second from the page cache
  echo "== run $run: today's path (the full frame first), bench --frames 1"
  $TIME $B bench $IN $FRAME --frames 1 --warmup 0 --no-count 2>&1 | grep -E "KiB_peak|dvr|memory"
  for f in 1 4 8; do
    echo "== run $run: --first-image --coarse-factor $f"
    $TIME $B bench $IN $FRAME --first-image --coarse-factor $f 2>&1
  done
  cat /proc/loadavg
done
