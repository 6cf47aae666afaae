#!/bin/bash
# Lighting cinematic (the progressive path tracer, issue 15) on the GPU: PSNR and SSIM
# against the frame's own converged image as a function of seconds, at 1920x1080 (the
# issue's goal: >= 35 dB within 2 s on an H100/H200). Build and carry as gpu-bench.sh says
# (build-gpu/bin and build-gpu/data with stanford/CThead and raw/cranium-ct), then run this
# from the repository root on the GPU machine.
set -x
. docs/bench/gpu-env.sh
# CThead, CT-Bone: converged at 4096 samples per pixel (another seed), measured at 0.25 ... 4 s.
$B accuracy $CT --device gpu --mode dvr --preset CT-Bone --azimuth 30 --size 1920x1080 \
  --lighting cinematic --converged-spp 4096 --checkpoints 0.25,0.5,1,2,4 2>&1
# The 512x512x400 CT, CT-Bone.
make_ct512
$B accuracy $V --device gpu --mode dvr --preset CT-Bone --azimuth 30 --size 1920x1080 \
  --lighting cinematic --converged-spp 4096 --checkpoints 0.25,0.5,1,2,4 2>&1
# Throughput: milliseconds per sample per pixel (fps column: samples per pixel per second).
$B bench $CT --device gpu --mode dvr --preset CT-Bone --lighting cinematic --sizes 1920x1080 \
  --frames 36 2>&1
