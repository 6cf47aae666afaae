#!/bin/bash
# Issue 35: a transfer-function edit's update on PoCL, before and after, one run after the other
# (bench --tf-drag: pairs of frames at a still camera, the table unchanged, then moved 1 HU; the
# update is the moved frame's median minus the unchanged one's). The 512x512x400 CT of
# make_ct512.py at /tmp/ct512.raw; CT-Bone dvr.
#   docs/bench/tf-drag-ab.sh BEFORE_CLI AFTER_CLI [SIZE] [PAIRS] [ROUNDS]
# e.g. docs/bench/tf-drag-ab.sh ../main/build/bin/voxray-cli build/bin/voxray-cli 1024x768 8 2
# The machine is shared: each run prints the load average and the process's CPU time.
before=$1 after=$2 size=${3:-1024x768} pairs=${4:-8} rounds=${5:-2}
V="/tmp/ct512.raw --raw-dims 512,512,400 --raw-type i16 --raw-spacing 0.4785,0.4785,0.405"
for round in $(seq "$rounds"); do
  for b in "$before" "$after"; do
    echo "== $b, round $round, load $(cut -d' ' -f1-3 /proc/loadavg)"
    # shellcheck disable=SC2086
    /usr/bin/time -f "cpu user %U s sys %S s wall %e s" "$b" bench $V --mode dvr --preset CT-Bone \
      --sizes "$size" --device cpu --tf-drag "$pairs" 2>&1 | grep -E "tf drag|^ct512|cpu user"
  done
done
echo "end load $(cut -d' ' -f1-3 /proc/loadavg)"
