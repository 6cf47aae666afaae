"""Raw inputs for the voxray-mpi tests (tests/mpi/CMakeLists.txt), written into the build tree.

ball.raw: 48x44x40 int16 little-endian, spacing 1 x 1.1 x 1.3 mm: a ball of 1000 in -1000 with a
two-millimetre ramp at its edge (smooth gradients) and a bump, placed off centre so that the
planes between 2 and 3 slabs cut it obliquely.
broken/: 12 slice files of 16x16 int16 with the last one cut short: only the rank whose slab
holds it fails.
"""
import os
import sys

import numpy as np

out = sys.argv[1]
os.makedirs(out, exist_ok=True)

nx, ny, nz = 48, 44, 40
sx, sy, sz = 1.0, 1.1, 1.3
z, y, x = np.meshgrid(np.arange(nz) * sz, np.arange(ny) * sy, np.arange(nx) * sx, indexing="ij")
r = np.sqrt((x - 22.0) ** 2 + (y - 25.0) ** 2 + (z - 27.0) ** 2)
bump = np.sqrt((x - 30.0) ** 2 + (y - 25.0) ** 2 + (z - 38.0) ** 2)
inside = np.clip(np.maximum((14.0 - r) / 2.0, (5.0 - bump) / 2.0) + 0.5, 0.0, 1.0)
ball = np.round(-1000.0 + 2000.0 * inside).astype("<i2")
ball.tofile(os.path.join(out, "ball.raw"))

broken = os.path.join(out, "broken")
os.makedirs(broken, exist_ok=True)
for k in range(1, 13):
    data = np.full((16, 16), 100 * k, dtype="<i2").tobytes()
    with open(os.path.join(broken, "slice%02d.raw" % k), "wb") as f:
        f.write(data[:100] if k == 12 else data)
