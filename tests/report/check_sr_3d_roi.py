"""A rectangle drawn in a coronal plane lies on several images: `voxray-cli export-sr --rect
10:5:2,40:5:8 --plane j` must give it as a closed SCOORD3D POLYGON in LPS mm (issue 37). The
corners are recomputed here from the files' Image Position and Orientation with pydicom, and
highdicom reads the Comprehensive 3D SR.

usage: check_sr_3d_roi.py REPORT.dcm SOURCE_FOLDER"""
import sys

import numpy as np

from sr_3d_files import lps, scoord3d_items, source_images

report_path = sys.argv[1]
images = source_images(sys.argv[2])
failures = []
found = scoord3d_items(report_path)
# One under each of the ROI's values: mean, SD, min, max, area.
if len(found) != 5:
    failures.append(f"{len(found)} SCOORD3D items, not 5")
corners = [(10, 5, 2), (40, 5, 2), (40, 5, 8), (10, 5, 8), (10, 5, 2)]
expected = np.concatenate([lps(images, *c) for c in corners])
for s in found:
    got = np.array(s.GraphicData, float)
    if s.GraphicType != "POLYGON":
        failures.append(f"graphic type {s.GraphicType}")
    if s.ReferencedFrameOfReferenceUID != images[0].FrameOfReferenceUID:
        failures.append(f"Frame of Reference {s.ReferencedFrameOfReferenceUID}")
    # FL (32-bit float) holds some hundred mm to better than 1e-3 mm.
    if got.shape != expected.shape or np.abs(got - expected).max() > 1e-3:
        failures.append(f"corners {got} mm, not {expected} mm")
if failures:
    sys.exit("\n".join(failures))
print("coronal rectangle as SCOORD3D POLYGON:", np.round(expected.reshape(-1, 3)[:4], 3).tolist())
