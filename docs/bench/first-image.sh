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
# The "today" lines time `render` (read, upload, tables, one frame) under /usr/bin/time, which
# any voxray-cli has: run the script with main's CLI for the figures before this change (its
# --first-image lines then fail: main has none). The lean build writes no PNG: render's
# "writes no images" error after the frame is expected, the time and peak RSS still count.
set -u
RAW=${1:?usage: first-image.sh RAW X,Y,Z [CLI]}
DIMS=${2:?usage: first-image.sh RAW X,Y,Z [CLI]}
if [ -n "${3:-}" ]; then B=$3; else . docs/bench/gpu-env.sh; fi
if [ ! -f "$RAW" ]; then
  python3 docs/bench/make_ball_raw.py ${DIMS//,/ } "$RAW" || exit 1
fi
IN="$RAW --raw-dims $DIMS --raw-type i16 --raw-rescale 1,0"
LOOK="--mode dvr --preset CT-Bone --device ${VOXRAY_DEVICE:-gpu}"
TIME="${TIME_BIN:-/usr/bin/time} -f %e_s_wall_%M_KiB_peak_RSS"  # TIME_BIN: a carried GNU time
ls -l "$RAW"; nproc; free -g | head -2; cat /proc/loadavg
# Run 1 reads RAW from disk unless it is in the page cache (a file just made is; for a cold
# read: sync; echo 3 > /proc/sys/vm/drop_caches), run 2 from the cache.
for run in 1 2; do
  echo "== run $run: today's path: render (the full frame is the first image)"
  $TIME $B render $IN $LOOK --size 1920x1080 -o /tmp/first-image.png 2>&1
  for f in 1 4 8; do
    echo "== run $run: --first-image --coarse-factor $f"
    $TIME $B bench $IN $LOOK --sizes 1920x1080 --first-image --coarse-factor $f 2>&1
  done
  cat /proc/loadavg
done
