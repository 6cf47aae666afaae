#!/bin/bash
# Kernel CPU ms per frame of iso frames, kernels A/B from one binary (VOXRAY_KERNEL_DIR; "-" =
# the embedded ones): perf cpu-clock:u samples (2 ms) in raycast.so, a LONG-frame bench run
# minus a 2-frame run, alternating the variants within each round (Session 8, iso).
# usage: iso-ab.sh ROUNDS LONG "LABEL:KERNELDIR ..." LANES...
# env: RAW (default the ct400 raw), RAWARGS (its raw flags), CLI, EXTRA (more bench flags)
rounds=$1 long=$2 variants=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
cli=${CLI:-$here/../../build/bin/voxray-cli}
raw=${RAW:-/work/ct/ct400_hu_le.raw}
rawargs=${RAWARGS:---raw-dims 512,512 --raw-type i16 --raw-spacing 1,1,1}
d=$(mktemp -d)
export POCL_CACHE_DIR=${POCL_CACHE_DIR:-$d/pocl}
run() { # dir lanes frames
  if [ "$1" = - ]; then unset VOXRAY_KERNEL_DIR; else export VOXRAY_KERNEL_DIR=$1; fi
  perf record -q -e cpu-clock:u -c 2000000 -o $d/p -- $cli bench $raw $rawargs --mode iso --iso 400 --orbit elevation --zoom 1.37 --sizes 512x384 --frames $3 --no-count --lanes $2 ${EXTRA:-} >/dev/null 2>&1
  echo $(( $(perf script -i $d/p -F ip,dso 2>/dev/null | grep -c raycast.so) * 2 ))
}
for r in $(seq $rounds); do
  for l in "$@"; do
    line="round $r lanes $l load $(cut -d' ' -f1 /proc/loadavg):"
    for v in $variants; do
      name=${v%%:*} dir=${v#*:}
      a=$(run $dir $l 2); b=$(run $dir $l $long)
      line="$line $name $(echo "scale=1; ($b - $a) / ($long - 2)" | bc)"
    done
    echo "$line"
  done
done
rm -rf $d
