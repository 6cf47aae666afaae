#!/usr/bin/env bash
# Issue 38 part 4: one frame over several devices, sort-last, on PoCL. Two sub-devices of one
# core each (--split 2) against the whole 2-core device: the same part kernel as one part
# (--split 1: the split's overhead, compositing included) and the one-device raycaster one ray
# per work-item (--kernel per-ray, the same march) and with packets (the CPU default).
# CThead, 512x384, 12 frames over the orbit, two interleaved rounds; medians. Writes docs/bench/multidev-pocl.txt.
# Usage: docs/bench/multidev-pocl.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
cli=$build/bin/voxray-cli
data=${VOXRAY_DATA:-../shared/data}
out=docs/bench/multidev-pocl.txt
cthead=("$data/stanford/CThead" --raw-dims 256,256 --raw-type i16 --raw-endian big
  --raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI)
common=(--sizes 512x384 --frames 12 --warmup 2)
modes=("--mode dvr --preset CT-Bone" "--mode iso --preset Iso-Bone" "--mode mip")
{
  echo "# $(date -u +%F) $(git rev-parse --short HEAD), PoCL: $($cli devices | grep -m1 -o 'pthread[^ ]*')"
  echo "# machine: $(nproc) cores shared with other helpers' builds and tests; load before: $(cat /proc/loadavg)"
  # Two rounds, the four configurations interleaved, so that the shared machine's load falls on
  # each alike.
  for round in 1 2; do
    for m in "${modes[@]}"; do
      echo "## round $round: $m"
      echo "# A: 2 sub-devices, 1 core each (--split 2)"
      VOXRAY_DEVICE=cpu $cli bench "${cthead[@]}" $m "${common[@]}" --split 2 | grep -v '^12 frames'
      echo "# B: 1 part on the 2-core device (--split 1: the part kernel, composite included)"
      VOXRAY_DEVICE=cpu $cli bench "${cthead[@]}" $m "${common[@]}" --split 1 | grep -v '^12 frames'
      echo "# C: one device, 2 cores: the raycaster, one ray per work-item (--kernel per-ray)"
      VOXRAY_DEVICE=cpu $cli bench "${cthead[@]}" $m "${common[@]}" --kernel per-ray --no-count |
        grep -E '^CThead'
      echo "# D: one device, 2 cores: the raycaster with packets (the CPU default)"
      VOXRAY_DEVICE=cpu $cli bench "${cthead[@]}" $m "${common[@]}" --no-count | grep -E '^CThead'
      echo "# load: $(cat /proc/loadavg)"
    done
  done
  echo "# columns of C and D: input size mode gradient kernel median_ms min_ms max_ms fps kernel_ms ..."
  echo "# load after: $(cat /proc/loadavg)"
} 2>&1 | tee "$out"
