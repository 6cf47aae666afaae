#!/usr/bin/env bash
# Issue 38 part 5: voxray-mpi (MPI ranks, each rendering its z slab on PoCL, IceT compositing)
# with 1, 2 and 3 ranks on this machine, against the one-device voxray-cli bench. CThead,
# 512x384, dvr / iso / mip, 10 frames after one (the kernel builds); medians in ms: the frame
# (icetDrawFrame on rank 0: every rank's part and the composite), the slowest rank's part and
# IceT's own ICET_COMPOSITE_TIME. Writes docs/bench/mpi-icet-pocl.txt.
# Usage: docs/bench/mpi-icet-pocl.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
mpi=$build/bin/voxray-mpi
data=${VOXRAY_DATA:-../shared/data}
out=docs/bench/mpi-icet-pocl.txt
cthead=("$data/stanford/CThead" --raw-dims 256,256 --raw-type i16 --raw-endian big
  --raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI)
modes=("--mode dvr --preset CT-Bone" "--mode iso --preset Iso-Bone" "--mode mip")
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_plm_rsh_agent=false
export VOXRAY_DEVICE=cpu
{
  echo "# $(date -u +%F) $(git rev-parse --short HEAD), $(nproc) cores shared with other helpers; load before: $(cat /proc/loadavg)"
  for round in 1 2; do
    for m in "${modes[@]}"; do
      for n in 1 2 3; do
        echo "## round $round, $n rank(s): $m"
        mpiexec --oversubscribe -n $n $mpi "${cthead[@]}" $m --size 512x384 --azimuth 30 \
          --elevation 20 --frames 11 2>&1 | grep -E '^rendered|^  rank [0-9]: part'
      done
    done
  done
  echo "# load after: $(cat /proc/loadavg)"
} | tee $out
