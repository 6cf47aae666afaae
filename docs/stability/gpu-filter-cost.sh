#!/bin/bash
# What exact interpolation costs on a GPU: the image3d_t path now reads 8 texels and
# interpolates in float (as the buffer path does) instead of the sampler's 8-bit-weight
# linear filter. Runs the previous build (build-gpu/base/voxray-cli, hardware filtering)
# and this one in alternating rounds on the same 512x512x400 CT (make_ct512.py from the
# carried cranium CT), 1920x1080, both storages, iso / dvr CT-Bone / mip. Log:
# docs/stability/gpu-filter-cost-h100.txt.
. docs/bench/gpu-env.sh
OLD=${B/bin\/voxray-cli/base\/voxray-cli}
python3 docs/bench/make_ct512.py build-gpu/gdata/raw/cranium-ct/cranium_256x256x108_s16le.raw \
  /tmp/ct512.raw
$B bench $V --device gpu --mode mip --sizes 64x48 --frames 2 --no-count 2>&1 | head -1
for round in 1 2 3; do
  for st in image buffer; do
    for m in "--mode iso --iso 300" "--mode dvr --preset CT-Bone" "--mode mip"; do
      for bin in "$OLD" "$B"; do
        row=$($bin bench $V --device gpu $m --storage $st --sizes 1920x1080 --frames 36 \
          --no-count 2>&1 | sed -n 2p)
        echo "round $round $st ${bin##* } | $row"
      done
    done
  done
done
