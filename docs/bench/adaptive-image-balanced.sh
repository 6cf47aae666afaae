#!/bin/bash
# Balanced (trilinear, Zucker-Hummel, CT-Bone, default camera) at 1024x768: plain 1.5 voxels
# (the preset) against adaptive image settings (THRESHOLD,K@STEP), taking turns in each round,
# PoCL's AVX-512 kernels and its AVX2 build (own kernel cache), both CTs; each figure the median
# of 3 frames after the first of one process. PSNR at 512x384 against the double-precision
# reference at 1/16 voxel (render --reference, same flags), and at 1024x768 against the plain
# frame of the same step.
out=${1:?usage: adaptive-image-balanced.sh OUT_DIR (with head-ref.png and ct-ref.png: render --reference at 512x384, --step 0.0625, the flags below)}
here=$(cd "$(dirname "$0")" && pwd)
cd "$out"
CLI=${CLI:-$here/../../build/bin/voxray-cli}
PY=${PYTHON:-$here/../../.venv/bin/python}
HEAD="render ${HEAD_RAW:?the CThead raw of equal-error-vs-vtk.sh} --raw-dims 256,256 --raw-type i16 --raw-spacing 1,1,2"
CT="render ${CT_RAW:?the ct400 raw of equal-error-vs-vtk.sh} --raw-dims 512,512 --raw-type i16 --raw-spacing 1,1,1"
R="--mode dvr --preset CT-Bone --gradient zucker-hummel --interp linear"
CFGS=${CFGS:-"off@1.5 8,4@1.5 16,4@1.5 16,2@1.5 24,4@1"}
isa_env() { [ $1 = avx2 ] && echo "POCL_LLVM_CPU_NAME=haswell POCL_KERNELLIB_NAME=avx2 POCL_CACHE_DIR=$out/pocl-avx2"; }
psnr() { $PY -c "
from skimage.io import imread
from skimage.metrics import peak_signal_noise_ratio as P
import numpy as np
a=imread('$1')[:,:,:3]; b=imread('$2')[:,:,:3]
print(99.0 if np.array_equal(a,b) else round(P(a,b,data_range=255),2))"; }
echo "load before: $(cat /proc/loadavg)"
for scene in HEAD CT; do
  ref=head-ref.png; [ $scene = CT ] && ref=ct-ref.png
  for c in $CFGS; do ai=${c%@*}; st=${c#*@}
    $CLI ${!scene} $R --size 512x384 --step $st --adaptive-image $ai -o p-$scene-$c.png > /dev/null 2>&1
    $CLI ${!scene} $R --size 1024x768 --step $st -o q-$scene-off-$st.png > /dev/null 2>&1
    $CLI ${!scene} $R --size 1024x768 --step $st --adaptive-image $ai -o q-$scene-$c.png 2> log2.txt > /dev/null
    echo "$scene $c: PSNR 512x384 vs reference $(psnr $ref p-$scene-$c.png) dB; 1024x768 vs plain $(psnr q-$scene-off-$st.png q-$scene-$c.png) dB; $(grep -o '[0-9]* of [0-9]* blocks refined' log2.txt)"
    for isa in avx512 avx2; do env $(isa_env $isa) $CLI ${!scene} $R --size 1024x768 --step $st --adaptive-image $ai -o warm.png > /dev/null 2>&1; done
  done
done
for round in 1 2 3; do
  for scene in HEAD CT; do
    for isa in avx512 avx2; do
      for c in $CFGS; do ai=${c%@*}; st=${c#*@}
        t=$(env $(isa_env $isa) $CLI ${!scene} $R --size 1024x768 --step $st --adaptive-image $ai --repeat 3 -o big.png 2>&1 | grep "^frames" | awk '{print $5}')
        echo "round $round $scene $isa $c: median ms $t (load $(cut -d' ' -f1 /proc/loadavg))"
      done
    done
  done
done
echo "load after: $(cat /proc/loadavg)"
