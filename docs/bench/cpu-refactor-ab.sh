#!/usr/bin/env bash
# Issue 33 on the CPU: frame times of two voxray-cli binaries on CThead, alternating in
# every round, on PoCL's AVX-512 build (16 lanes) and its AVX2 build (haswell, 8 lanes).
# usage: docs/bench/cpu-refactor-ab.sh OLD_CLI NEW_CLI [ROUNDS]   prints one row per run
set -uo pipefail
old=$1 new=$2 rounds=${3:-3}
here=$(cd "$(dirname "$0")" && pwd)
ct="$here/../../../shared/data/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big \
--raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI"
cache=$(mktemp -d)
trap 'rm -rf "$cache"' EXIT
for r in $(seq "$rounds"); do
  for cpu in native haswell; do
    for mode in iso dvr mip cinematic; do
      for which in old new; do
        flags="--mode $mode"
        [[ $mode == cinematic ]] && flags="--mode dvr --lighting cinematic"
        env=(POCL_CACHE_DIR=$cache/$cpu)
        [[ $cpu == haswell ]] && env+=(POCL_LLVM_CPU_NAME=haswell POCL_KERNELLIB_NAME=avx2)
        # shellcheck disable=SC2086
        row=$(env "${env[@]}" "${!which}" bench $ct $flags --device cpu --sizes 512x384 \
          --frames 16 2>&1 | grep -A1 median_ms | tail -1)
        echo "round $r $cpu $mode $which $row"
      done
    done
  done
done
