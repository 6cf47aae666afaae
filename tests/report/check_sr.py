"""Reads a TID 1500 report written by `voxray-cli export-sr` back with highdicom/pydicom and
checks its values, units and image references against the source series, recomputed here
from the DICOM files themselves (pydicom), not from Voxray.

usage: check_sr.py REPORT.dcm SOURCE_FOLDER
The report holds (see tests/report/CMakeLists.txt): line 1 100:200:1-130:240:1, angle 1
100:200:1,130:240:1,200:100:1, ellipse 1 240:90:1-260:110:1, rect 1 10:10:1-40:50:1, line 2 10:10:0-20:20:3 (across
slices: no image region)."""
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
sr = hd.sr.EnhancedSR.from_dataset(ds)
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

evidence = [r.ReferencedSOPInstanceUID for e in ds.CurrentRequestedProcedureEvidenceSequence
            for s in e.ReferencedSeriesSequence for r in s.ReferencedSOPSequence]
expect(sorted(evidence) == sorted([slice1.SOPInstanceUID] + ends), f"evidence {evidence}")

if failures:
    sys.exit("\n".join(failures))
print("SR values, units and references as the source images give them")
