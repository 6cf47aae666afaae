"""Segment groups that reference their DICOM SEG (issue 37): `voxray-cli export-sr --labels-raw
LABELS --seg SEG.dcm` on the pelvis with two boxes (labels 1 and 3, so label 3 is the SEG's
segment 2). highdicom reads the report as a Comprehensive 3D SR and finds, per TID 1411
Volumetric ROI group: the Referenced Segment (121191, DCM) naming the SEG file's SOP Class and
Instance UID and the segment whose label the tracking identifier names; the Source series for
segmentation (121232, DCM), the pelvis' Series Instance UID; the volume, equal to the SEG's
voxels of that segment counted here with pydicom (and to the CSV, the workstation model's
statistics, and to the boxes made here); the centroid, a SCOORD3D POINT in LPS mm with the
pelvis' Frame of Reference, equal to the mean position of the SEG's pixels of that segment.

usage: check_sr_seg.py REPORT.dcm SEG.dcm SOURCE_FOLDER CSV BOXES_JSON"""
import csv
import json
import sys

import numpy as np

from sr_3d_files import lps, source_images

try:
    import highdicom as hd
    import pydicom
    from pydicom.sr.codedict import codes
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")

report_path, seg_path, source, csv_path, boxes_path = sys.argv[1:6]
images = source_images(source)
boxes = json.load(open(boxes_path))  # {"label": [i0, i1, j0, j1, k0, k1]} inclusive
seg = pydicom.dcmread(seg_path)
ds = pydicom.dcmread(report_path)
sr = hd.sr.Comprehensive3DSR.from_dataset(ds)
failures = []

# The SEG, read independently: each segment's pixels in LPS mm, from its frames' positions.
row_dir = np.array(seg.SharedFunctionalGroupsSequence[0].PlaneOrientationSequence[0]
                   .ImageOrientationPatient[:3], float)
col_dir = np.array(seg.SharedFunctionalGroupsSequence[0].PlaneOrientationSequence[0]
                   .ImageOrientationPatient[3:], float)
measures = seg.SharedFunctionalGroupsSequence[0].PixelMeasuresSequence[0]
row_mm, col_mm = (float(x) for x in measures.PixelSpacing)
voxel_mm3 = row_mm * col_mm * float(measures.SliceThickness)
frames = seg.pixel_array.reshape(-1, seg.Rows, seg.Columns)
points = {}
for frame, group in zip(frames, seg.PerFrameFunctionalGroupsSequence):
    number = int(group.SegmentIdentificationSequence[0].ReferencedSegmentNumber)
    origin = np.array(group.PlanePositionSequence[0].ImagePositionPatient, float)
    r, c = np.nonzero(frame)
    mm = origin + np.outer(c * col_mm, row_dir) + np.outer(r * row_mm, col_dir)
    points.setdefault(number, []).append(mm)
points = {n: np.concatenate(p) for n, p in points.items()}
labels = {int(s.SegmentNumber): s.SegmentLabel for s in seg.SegmentSequence}

model = {}  # the CSV's volume per label: the statistics the workstation shows
for r in csv.DictReader(open(csv_path)):
    if r["kind"] == "segment" and r["quantity"] == "volume":
        model[r["label"]] = float(r["value"])

groups = sr.content.get_volumetric_roi_measurement_groups()
if len(groups) != len(boxes):
    failures.append(f"{len(groups)} volumetric groups, expected {len(boxes)}")
for g in groups:
    label = g.tracking_identifier  # "segment L Segment L"
    box_label = label.split()[1]
    ref = g.referenced_segment
    if ref is None:
        failures.append(f"{label}: no Referenced Segment")
        continue
    if ref.referenced_sop_instance_uid != seg.SOPInstanceUID:
        failures.append(f"{label}: references {ref.referenced_sop_instance_uid}, "
                        f"the SEG is {seg.SOPInstanceUID}")
    if ref.referenced_sop_class_uid != seg.SOPClassUID:
        failures.append(f"{label}: SOP class {ref.referenced_sop_class_uid}")
    numbers = ref.referenced_segment_numbers
    if not numbers or len(numbers) != 1:
        failures.append(f"{label}: segment numbers {numbers}")
        continue
    number = numbers[0]
    if labels.get(number) != f"Segment {box_label}":
        failures.append(f"{label}: names segment {number}, the SEG's {labels.get(number)!r}")
    series = ref.source_series_for_segmentation
    if series is None or series.value != images[0].SeriesInstanceUID:
        failures.append(f"{label}: source series {series and series.value}")
    volumes = [m for m in g.get_measurements() if m.name == codes.SCT.Volume]
    if len(volumes) != 1 or volumes[0].unit.value != "mm3":
        failures.append(f"{label}: volume items {volumes}")
        continue
    volume = float(volumes[0].value)
    counted = len(points[number]) * voxel_mm3
    i0, i1, j0, j1, k0, k1 = boxes[box_label]
    made = (i1 - i0 + 1) * (j1 - j0 + 1) * (k1 - k0 + 1) * voxel_mm3
    # 1e-9 relative: the SR's 9 significant digits.
    for what, want in (("SEG voxels", counted), ("the boxes made", made),
                       ("the CSV (model)", model.get(label, float("nan")))):
        if not abs(volume - want) <= 1e-9 * want:
            failures.append(f"{label}: volume {volume} mm3 != {what} {want}")
    # The centroid: the only SCOORD3D of the group, a POINT under the volume.
    scoords = [c for c in volumes[0][0].ContentSequence if c.ValueType == "SCOORD3D"]
    if len(scoords) != 1 or scoords[0].GraphicType != "POINT":
        failures.append(f"{label}: SCOORD3D under the volume {scoords}")
        continue
    if scoords[0].ReferencedFrameOfReferenceUID != images[0].FrameOfReferenceUID:
        failures.append(f"{label}: Frame of Reference {scoords[0].ReferencedFrameOfReferenceUID}")
    point = np.array(scoords[0].GraphicData, float)
    from_seg = points[number].mean(axis=0)
    # The box's centre k is a whole slice (odd slice counts): from the source files' headers.
    from_box = lps(images, (i0 + i1) / 2, (j0 + j1) / 2, (k0 + k1) // 2)
    # 0.01 mm: SCOORD3D is float32 (about 1e-4 mm at 1000 mm) and the SEG's DS positions.
    for what, want in (("the SEG's pixels", from_seg), ("the box", from_box)):
        if np.abs(point - want).max() > 0.01:
            failures.append(f"{label}: centroid {point} != {what} {want}")
    print(f"{label}: SEG segment {number} ({labels[number]}), {volume / 1000:.6g} mL, "
          f"centroid {np.round(point, 3)} mm")

if failures:
    sys.exit("\n".join(failures))
