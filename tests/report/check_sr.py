"""Reads a TID 1500 report written by `voxray-cli export-sr` back with highdicom/pydicom and
checks its values, units and image references against the source series, recomputed here
from the DICOM files themselves (pydicom), not from Voxray.

usage: check_sr.py REPORT.dcm SOURCE_FOLDER
The report holds (see tests/report/CMakeLists.txt): line 1 100:200:1-130:240:1, angle 1
100:200:1,130:240:1,200:100:1, ellipse 1 240:90:1-260:110:1, rect 1 10:10:1-40:50:1, line 2 10:10:0-20:20:3 (across
slices: no image region; its points as SCOORD3D in LPS mm, so the report is a Comprehensive 3D
SR)."""
import math
import sys
from pathlib import Path

try:
    import highdicom as hd
    import numpy as np
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")

report_path, source = sys.argv[1], Path(sys.argv[2])
failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)


# The series sorted by position along its normal: slice k of Voxray's volume.
images = [pydicom.dcmread(p) for p in sorted(source.iterdir()) if p.suffix == ".dcm"]
normal = np.cross(np.array(images[0].ImageOrientationPatient[:3], float),
                  np.array(images[0].ImageOrientationPatient[3:], float))
images.sort(key=lambda d: float(np.dot(normal, np.array(d.ImagePositionPatient, float))))
slice1 = images[1]
row_mm, col_mm = (float(x) for x in slice1.PixelSpacing)  # row spacing, column spacing

ds = pydicom.dcmread(report_path)
expect(ds.SOPClassUID == "1.2.840.10008.5.1.4.1.1.88.34", f"SOP class {ds.SOPClassUID}, not "
       "Comprehensive 3D SR")
sr = hd.sr.Comprehensive3DSR.from_dataset(ds)
groups = {g.tracking_identifier: g for g in sr.content.get_image_measurement_groups()}
expect(sorted(groups) == ["angle 1", "ellipse 1", "line 1", "line 2", "rect 1"], f"groups {sorted(groups)}")
expect(ds.StudyInstanceUID == slice1.StudyInstanceUID, "the report is not in the images' study")


def measurements(label):
    return list(groups[label].get_measurements())


def close(a, b, rel=1e-7, abs_=1e-6):
    # DS keeps 9 significant digits: 1e-7 relative is above their rounding.
    return abs(a - b) <= max(abs_, rel * abs(b))


# Length: (30, 40) pixels apart on one slice.
(length,) = measurements("line 1")
expected = math.hypot(30 * col_mm, 40 * row_mm)
expect(length.name.value == "410668003" and length.unit.value == "mm", "length code/unit")
expect(close(float(length.value), expected), f"length {length.value} != {expected}")

# Angle at (130, 240) between (100, 200) and (200, 100), in mm.
(angle,) = measurements("angle 1")
u = np.array([-30 * col_mm, -40 * row_mm])
w = np.array([70 * col_mm, -140 * row_mm])
expected = math.degrees(math.acos(np.dot(u, w) / np.linalg.norm(u) / np.linalg.norm(w)))
expect(angle.unit.value == "deg", "angle unit")
expect(close(float(angle.value), expected), f"angle {angle.value} != {expected}")

hu = slice1.pixel_array.astype(float) * float(slice1.RescaleSlope) + float(slice1.RescaleIntercept)
y, x = np.mgrid[0:hu.shape[0], 0:hu.shape[1]]


def check_roi(label, inside, area):
    values = hu[inside]
    expected = {"Mean": values.mean(), "Standard Deviation": values.std(ddof=1),
                "Minimum": values.min(), "Maximum": values.max()}
    seen = {}
    for m in measurements(label):
        if m.name.value == "42798000":  # Area
            expect(m.unit.value == "mm2", "area unit")
            expect(close(float(m.value), area), f"{label}: area {m.value} != {area}")
            seen["Area"] = True
            continue
        expect(m.name.value == "112031" and m.unit.value == "[hnsf'U]",
               f"{label}: code/unit {m.name} {m.unit}")
        d = m.derivation.meaning
        seen[d] = True
        expect(close(float(m.value), expected[d]), f"{label}: {d} {m.value} != {expected[d]}")
    expect(sorted(seen) == ["Area", "Maximum", "Mean", "Minimum", "Standard Deviation"],
           f"{label}: values {seen}")


# Ellipse: centre (250, 100), semi-axes 10 pixels; a pixel counts when its centre is inside
# or on the boundary (1e-9: the engine's rounding tolerance). Rect: columns 10..40, rows 10..50.
check_roi("ellipse 1", ((x - 250) / 10) ** 2 + ((y - 100) / 10) ** 2 <= 1 + 1e-9,
          math.pi * 10 * col_mm * 10 * row_mm)
check_roi("rect 1", (x >= 10) & (x <= 40) & (y >= 10) & (y <= 50), 30 * col_mm * 40 * row_mm)


# Image references: every value of the slice-1 measurements has an image region (SCOORD)
# selected from slice 1's SOP instance; line 2 crosses slices and has none.
def scoords(item):
    for child in getattr(item, "ContentSequence", []):
        if child.ValueType == "SCOORD":
            yield child
        yield from scoords(child)


def group_item(label):
    for item in ds.ContentSequence:
        for g in getattr(item, "ContentSequence", []):
            for c in getattr(g, "ContentSequence", []):
                if getattr(c, "TextValue", None) == label:
                    return g
    return None


for label, graphic in [("line 1", [100.5, 200.5, 130.5, 240.5]),
                       ("angle 1", [100.5, 200.5, 130.5, 240.5, 200.5, 100.5]),
                       ("ellipse 1", [240.5, 100.5, 260.5, 100.5, 250.5, 90.5, 250.5, 110.5]),
                       ("rect 1", [10.5, 10.5, 40.5, 10.5, 40.5, 50.5, 10.5, 50.5, 10.5, 10.5])]:
    g = group_item(label)
    found = list(scoords(g)) if g is not None else []
    expect(len(found) == len(measurements(label)), f"{label}: {len(found)} image regions")
    for s in found:
        expect(list(map(float, s.GraphicData)) == graphic, f"{label}: graphic data {s.GraphicData}")
        ref = s.ContentSequence[0].ReferencedSOPSequence[0]
        expect(ref.ReferencedSOPInstanceUID == slice1.SOPInstanceUID, f"{label}: references "
               f"{ref.ReferencedSOPInstanceUID}, not slice 1's {slice1.SOPInstanceUID}")
        expect(ref.ReferencedSOPClassUID == slice1.SOPClassUID, f"{label}: SOP class")
# Line 2 runs from slice 0 to slice 3: no one image region, the images of its two ends.
g = group_item("line 2")
expect(g is not None and not list(scoords(g)), "line 2 crosses slices: no image region")
ends = [images[0].SOPInstanceUID, images[3].SOPInstanceUID]
refs = [r.ReferencedSOPSequence[0].ReferencedSOPInstanceUID for m in measurements("line 2")
        for r in m.referenced_images]
expect(refs == ends, f"line 2 references {refs}, not its ends' images {ends}")



# Line 2's points in patient coordinates, recomputed from the files: voxel (i, j) of slice k
# is at ImagePositionPatient + i * column spacing * row direction + j * row spacing * column
# direction (PS3.3 C.7.6.2.1.1). Under each of its values: SCOORD3D, FoR of the images.
def lps(i, j, k):
    d = images[k]
    o = np.array(d.ImageOrientationPatient, float)
    r_mm, c_mm = (float(x) for x in d.PixelSpacing)
    return np.array(d.ImagePositionPatient, float) + i * c_mm * o[:3] + j * r_mm * o[3:]


def scoords3d(item):
    for child in getattr(item, "ContentSequence", []):
        if child.ValueType == "SCOORD3D":
            yield child
        yield from scoords3d(child)


found = list(scoords3d(g)) if g is not None else []
expect(len(found) == len(measurements("line 2")), f"line 2: {len(found)} SCOORD3D")
expected = np.concatenate([lps(10, 10, 0), lps(20, 20, 3)])
for s3 in found:
    expect(s3.GraphicType == "POLYLINE", f"line 2: graphic type {s3.GraphicType}")
    expect(s3.RelationshipType == "INFERRED FROM", f"line 2: {s3.RelationshipType}")
    expect(s3.ConceptNameCodeSequence[0].CodeValue == "121112", "line 2: not Source of Measurement")
    expect(s3.ReferencedFrameOfReferenceUID == images[0].FrameOfReferenceUID,
           f"line 2: Frame of Reference {s3.ReferencedFrameOfReferenceUID}")
    # GraphicData is FL (32-bit): 1e-3 mm holds for coordinates of some hundred mm.
    got = np.array(s3.GraphicData, float)
    expect(got.shape == expected.shape and np.abs(got - expected).max() < 1e-3,
           f"line 2: points {got} mm, not {expected} mm")
# Its length is the distance of those points (the pydicom positions give it too).
(length2,) = measurements("line 2")
expect(close(float(length2.value), float(np.linalg.norm(expected[3:] - expected[:3]))),
       f"line 2: length {length2.value}")

evidence = [r.ReferencedSOPInstanceUID for e in ds.CurrentRequestedProcedureEvidenceSequence
            for s in e.ReferencedSeriesSequence for r in s.ReferencedSOPSequence]
expect(sorted(evidence) == sorted([slice1.SOPInstanceUID] + ends), f"evidence {evidence}")

if failures:
    sys.exit("\n".join(failures))
print("SR values, units and references as the source images give them")
