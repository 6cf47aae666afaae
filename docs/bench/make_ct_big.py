#!/usr/bin/env python3
"""Writes a large int16 little-endian CT (HU) from the 512x512x400 one (make_ct512.py) by
nearest neighbour: FACTOR times in x and y, NZ slices in z. Issue 38's 8 GiB case is
FACTOR 4, NZ 1024: 2048x2048x1024, spacing 0.1196 x 0.1196 x 0.1582 mm.
Standard library only (the GPU machines have no numpy).

usage: make_ct_big.py CT512.raw OUT.raw [FACTOR] [NZ]
"""
import array
import sys

src, out_path = sys.argv[1], sys.argv[2]
factor = int(sys.argv[3]) if len(sys.argv) > 3 else 4
nz_out = int(sys.argv[4]) if len(sys.argv) > 4 else 1024
n, nz = 512, 400
data = array.array("h")
with open(src, "rb") as f:
    data.frombytes(f.read())
width = n * factor


def plane(z):
    rows = []
    for y in range(n):
        row = data[(z * n + y) * n:(z * n + y + 1) * n]
        wide = array.array("h", bytes(2 * width))
        for k in range(factor):
            wide[k::factor] = row
        rows.append(wide.tobytes() * factor)
    return b"".join(rows)


last, cached = -1, b""
with open(out_path, "wb") as out:
    for z in range(nz_out):
        sz = min(nz - 1, z * nz // nz_out)
        if sz != last:
            last, cached = sz, plane(sz)
        out.write(cached)
