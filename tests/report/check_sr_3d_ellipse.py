"""Ellipses drawn in a coronal plane lie on several images: `voxray-cli export-sr --ellipse
10:5:2,40:5:8 --ellipse 100:5:1,104:5:21 --plane j` must give each as a SCOORD3D ELLIPSE in
LPS mm: its major axis' two ends, then its minor axis' (PS3.3 C.18.9.1.2). The four points are
recomputed here from the files' Image Position, Orientation and Pixel Spacing with pydicom
(which axis is the major one: the longer in mm), and highdicom reads the Comprehensive 3D SR.

usage: check_sr_3d_ellipse.py REPORT.dcm SOURCE_FOLDER"""
import sys

import numpy as np

from sr_3d_files import lps as lps_in, scoord3d_items, source_images

report_path = sys.argv[1]
images = source_images(sys.argv[2])


def lps(i, j, k):
    return lps_in(images, i, j, k)


def axis_points(a, b):
    """The ellipse in the box A..B of the coronal plane (j fixed): the ends of its axis along
    i and of its axis along k, the longer in mm first."""
    ci, ck, j = (a[0] + b[0]) / 2, (a[2] + b[2]) / 2, a[1]
    along_i = [lps(a[0], j, ck), lps(b[0], j, ck)]
    along_k = [lps(ci, j, a[2]), lps(ci, j, b[2])]
    length = lambda p: np.linalg.norm(p[1] - p[0])
    first, second = (along_i, along_k) if length(along_i) >= length(along_k) else (along_k, along_i)
    return np.concatenate(first + second)


failures = []
found = scoord3d_items(report_path)
expected = [axis_points((10, 5, 2), (40, 5, 8)), axis_points((100, 5, 1), (104, 5, 21))]
matched = [0, 0]
for s in found:
    got = np.array(s.GraphicData, float)
    if s.GraphicType != "ELLIPSE":
        failures.append(f"graphic type {s.GraphicType}")
        continue
    if s.ReferencedFrameOfReferenceUID != images[0].FrameOfReferenceUID:
        failures.append(f"Frame of Reference {s.ReferencedFrameOfReferenceUID}")
    # FL (32-bit float) holds some hundred mm to better than 1e-3 mm.
    errors = [np.abs(got - e).max() if got.shape == e.shape else np.inf for e in expected]
    best = int(np.argmin(errors))
    if errors[best] > 1e-3:
        failures.append(f"ellipse points {got.reshape(-1, 3).tolist()} mm are neither ellipse's "
                        f"axis ends (nearest off by {errors[best]:.4g} mm)")
        continue
    matched[best] += 1
    p = got.reshape(4, 3)
    # An ellipse's axes cross at their middles, at right angles, the first the longer.
    if np.abs((p[0] + p[1]) / 2 - (p[2] + p[3]) / 2).max() > 1e-3:
        failures.append("the axes do not cross at their middles")
    if abs(np.dot(p[1] - p[0], p[3] - p[2])) > 1e-3 * np.linalg.norm(p[1] - p[0]) ** 2:
        failures.append("the axes are not at right angles")
    if np.linalg.norm(p[1] - p[0]) < np.linalg.norm(p[3] - p[2]):
        failures.append("the minor axis comes first")
# Each ellipse gives its coordinates under every one of its values.
if min(matched) == 0:
    failures.append(f"SCOORD3D ellipses found per ROI: {matched} ({len(found)} SCOORD3D items)")
if failures:
    sys.exit("\n".join(failures))
for e, n in zip(expected, matched):
    print(f"ellipse under {n} values, axis ends (mm):", np.round(e.reshape(4, 3), 3).tolist())
