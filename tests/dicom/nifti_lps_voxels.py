"""Prints every voxel of a NIfTI file as its LPS centre and its values, one line a voxel:
"x y z v0 v1 ..." (one value per volume of a 4D file). nibabel reads the file; its affine
(RAS+) is turned to LPS by negating x and y. The first line is "shape A B C [T]"."""
import sys

import nibabel
import numpy as np

image = nibabel.load(sys.argv[1])
data = np.asarray(image.dataobj, dtype=np.float64) * (image.dataobj.slope or 1.0) + (
    image.dataobj.inter or 0.0)
if data.ndim == 3:
    data = data[..., np.newaxis]
affine = image.affine.copy()
affine[:2, :] *= -1  # RAS+ to LPS
print("shape", *data.shape)
index = np.indices(data.shape[:3]).reshape(3, -1)
centres = affine[:3, :3] @ index + affine[:3, 3:4]
values = data.reshape(-1, data.shape[3])  # C order: the same order as index
out = sys.stdout
for n in range(index.shape[1]):
    out.write("%.6f %.6f %.6f %s\n" % (centres[0, n], centres[1, n], centres[2, n],
                                       " ".join("%g" % v for v in values[n])))
