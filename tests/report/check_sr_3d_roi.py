"""A rectangle drawn in a coronal plane lies on several images: `voxray-cli export-sr --rect
10:5:2,40:5:8 --plane j` must give it as a closed SCOORD3D POLYGON in LPS mm (issue 37). The
corners are recomputed here from the files' Image Position and Orientation with pydicom, and
highdicom reads the Comprehensive 3D SR.

usage: check_sr_3d_roi.py REPORT.dcm SOURCE_FOLDER"""
import sys
from pathlib import Path

try:
    import highdicom as hd
    import numpy as np
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")

report_path, source = sys.argv[1], Path(sys.argv[2])
images = [pydicom.dcmread(p) for p in sorted(source.iterdir()) if p.suffix == ".dcm"]
normal = np.cross(np.array(images[0].ImageOrientationPatient[:3], float),
                  np.array(images[0].ImageOrientationPatient[3:], float))
images.sort(key=lambda d: float(np.dot(normal, np.array(d.ImagePositionPatient, float))))


def lps(i, j, k):  # PS3.3 C.7.6.2.1.1: column index i along the row direction
    d = images[k]
    o = np.array(d.ImageOrientationPatient, float)
    r_mm, c_mm = (float(x) for x in d.PixelSpacing)
    return np.array(d.ImagePositionPatient, float) + i * c_mm * o[:3] + j * r_mm * o[3:]


ds = pydicom.dcmread(report_path)
hd.sr.Comprehensive3DSR.from_dataset(ds)  # highdicom reads it as its IOD
failures = []


def walk(item):
    for child in getattr(item, "ContentSequence", []):
        yield child
        yield from walk(child)


found = [i for i in walk(ds) if i.ValueType == "SCOORD3D"]
# One under each of the ROI's values: mean, SD, min, max, area.
if len(found) != 5:
    failures.append(f"{len(found)} SCOORD3D items, not 5")
corners = [(10, 5, 2), (40, 5, 2), (40, 5, 8), (10, 5, 8), (10, 5, 2)]
expected = np.concatenate([lps(*c) for c in corners])
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
