#!/usr/bin/env python3
"""Writes a large CT-like int16 little-endian raw volume for the first-image bench (issue 38).

An ellipsoidal head: air (-1000 HU), skin (0), a bone shell (1000), brain (40), stored as HU
(use --raw-rescale 1,0 or none). Standard library only (the GPU machines have no numpy); one
slice at a time, so it needs little memory.

usage: make_ball_raw.py X Y Z OUT.raw
"""
import array
import sys

nx, ny, nz = (int(a) for a in sys.argv[1:4])
out_path = sys.argv[4]
values = [(1.0, 0), (0.93, 1000), (0.88, 40)]  # (radius below which, HU), outside in
with open(out_path, "wb") as f:
    for z in range(nz):
        dz = ((z - nz / 2) / (0.47 * nz)) ** 2
        rows = array.array("h")
        for y in range(ny):
            dy = ((y - ny / 2) / (0.42 * ny)) ** 2
            row = array.array("h", [-1000]) * nx
            for limit, hu in values:
                left = limit * limit - dz - dy
                if left <= 0:
                    break
                half = int(left ** 0.5 * 0.45 * nx)
                lo, hi = max(0, nx // 2 - half), min(nx, nx // 2 + half)
                row[lo:hi] = array.array("h", [hu]) * (hi - lo)
            rows.extend(row)
        if sys.byteorder != "little":
            rows.byteswap()
        f.write(rows.tobytes())
