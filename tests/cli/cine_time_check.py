"""(Pillow reads the PNGs: highdicom depends on it, so the venv has it.)
`movie --cine time` of the beating sphere (32x32x16, 1.5 x 1.5 x 3 mm, 10 phases): frame t
is the axial middle slice (k = 7) of phase t, so its bright pixels (300 HU at the top of the
window) are the pixel centres inside the sphere's cross-section there, radius
sqrt(r(t)^2 - 1.5^2) with r(t) = 24 + 8 sin(2 pi t / 10) mm. Counts must match exactly."""
import glob
import math
import sys

import numpy as np
from PIL import Image

frames = sorted(glob.glob(sys.argv[1] + "/*.png"))
assert len(frames) == 10, frames
for t, path in enumerate(frames):
    r = 24 + 8 * math.sin(2 * math.pi * t / 10)
    expected = sum(1 for i in range(32) for j in range(32)
                   if ((i - 15.5) * 1.5) ** 2 + ((j - 15.5) * 1.5) ** 2 + 1.5 ** 2 <= r * r)
    got = int((np.asarray(Image.open(path))[..., 0] > 128).sum())
    assert got == expected, f"frame {t}: {got} bright pixels, expected {expected}"
print("10 frames follow the phases")
