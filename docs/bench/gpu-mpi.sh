#!/bin/bash
# Issue 38 part 5 on the 2-GPU machine: voxray-mpi with 1 and 2 ranks (one GPU each, IceT
# compositing through Open MPI's shared memory) on heavy frames as the 2-GPU goal takes them
# (empty-space skipping off) at 4K, dvr and mip, IceT on float and on 8-bit colour, on the
# 512x512x400 CT and the 2048x2048x1024 CT (8 GiB, make_ct_big.py; each rank reads its slab
# alone). Before: build voxray-mpi in build-gpu, run gpu-mpi-pack.sh, carry as gpu-round6.sh
# says. Run from the root: docs/bench/gpu-mpi.sh [small|big|both|bytes]
# (bytes: the 8 GiB CT, dvr, IceT on bytes only)
set -x
. docs/bench/gpu-env.sh
. docs/bench/gpu-mpi-env.sh
heavy="--size 3840x2160 --azimuth 30 --elevation 20 --frames 6 --ess off"
ranks() {  # INPUT...: 1 rank then 2 ranks, IceT on each of COLOURS, RUNS times
  for run in ${RUNS:-1 2}; do
    for colour in ${COLOURS:-float bytes}; do
      for n in 1 2; do
        echo "## run $run, $n rank(s), --icet-colour $colour: $*"
        # shellcheck disable=SC2086
        $M -n $n "$R/voxray-mpi" "$@" $heavy --icet-colour $colour 2>&1 |
          grep -E '^rendered|rank [0-9]:|rror'
      done
    done
  done
}
BIG="/tmp/ctbig.raw --raw-dims 2048,2048,1024 --raw-type i16 --raw-spacing 0.1196,0.1196,0.1582"
make_big() {
  [[ -e /tmp/ctbig.raw ]] || {
    make_ct512
    python3 docs/bench/make_ct_big.py /tmp/ct512.raw /tmp/ctbig.raw 4 1024
  }
}
case ${1:-both} in
  small | both)
    make_ct512
    # shellcheck disable=SC2086
    ranks $V --mode dvr --preset CT-Bone
    # shellcheck disable=SC2086
    ranks $V --mode mip
    ;;&
  big | both)
    make_big
    # shellcheck disable=SC2086
    ranks $BIG --mode dvr --preset CT-Bone
    # shellcheck disable=SC2086
    ranks $BIG --mode mip
    ;;
  bytes)
    make_big
    # shellcheck disable=SC2086
    COLOURS=bytes RUNS="1 2 3" ranks $BIG --mode dvr --preset CT-Bone
    ;;
esac
