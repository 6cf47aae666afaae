#!/usr/bin/env python3
"""Writes a 512x512x400 int16 little-endian CT (HU) for the bench's large-volume cases.

The shared data has no 512x512x400 CT, so this resamples the cranium CT
(../shared/data/raw/cranium-ct, 256x256x108, 0.957 x 0.957 x 1.5 mm) by nearest neighbour:
2x in x and y, 400/108 in z. Spacing of the result: 0.4785 x 0.4785 x 0.405 mm.
Standard library only (the GPU machines have no numpy).

usage: make_ct512.py [SRC] OUT.raw
"""
import array
import sys

args = sys.argv[1:]
src = args[0] if len(args) > 1 else "../shared/data/raw/cranium-ct/cranium_256x256x108_s16le.raw"
out_path = args[-1]
nx, ny, nz = 256, 256, 108
data = array.array("h")
with open(src, "rb") as f:
    data.frombytes(f.read())
if sys.byteorder != "little":
    data.byteswap()
with open(out_path, "wb") as out:
    for z in range(400):
        sz = min(nz - 1, z * nz // 400)
        plane = array.array("h")
        for y in range(512):
            row = data[(sz * ny + y // 2) * nx:(sz * ny + y // 2 + 1) * nx]
            wide = array.array("h", bytes(2 * 512))
            wide[0::2] = row
            wide[1::2] = row
            plane.extend(wide)
        out.write(plane.tobytes())
print(out_path, "512x512x400 int16 LE, spacing 0.4785,0.4785,0.405")
