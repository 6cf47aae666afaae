"""Independent readers check what Voxray's segmentation writers wrote (issue 34).

check_segment_files.py nifti|nrrd|seg FILE EXPECTED.json
check_segment_files.py source SEG SOURCE_DICOM_FOLDER

Exits 0 when every check holds; otherwise prints what differs and exits 1. Exits 3 when a
reader is missing (run scripts/bootstrap).
"""
import json
import os
import sys

try:
    import numpy as np
    import nibabel
    import nrrd
    import pydicom
    import highdicom as hd
except ImportError as e:  # the venv scripts/bootstrap makes
    print(f"missing test reader ({e}); run scripts/bootstrap")
    sys.exit(3)

failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)


def counts_of(labels):
    values, counts = np.unique(labels, return_counts=True)
    return {str(int(v)): int(c) for v, c in zip(values, counts) if v != 0}


def check_nifti(path, want):
    img = nibabel.load(path)
    data = np.asarray(img.dataobj)
    expect(data.dtype == np.uint8, f"dtype {data.dtype}, want uint8")
    expect(list(data.shape) == want["dims"], f"shape {data.shape}, want {want['dims']}")
    # 1e-4 mm: the header stores float32 positions of up to ~1000 mm (7 digits).
    for name, affine in (("sform", img.get_sform()), ("qform", img.get_qform()), ("affine", img.affine)):
        diff = np.abs(np.asarray(affine) - np.asarray(want["affine"])).max()
        expect(diff <= 1e-4, f"{name} differs from the volume's RAS affine by {diff} mm:\n{affine}")
    expect(int(img.header["sform_code"]) > 0 and int(img.header["qform_code"]) > 0, "sform/qform code 0")
    expect(counts_of(data) == want["counts"], f"counts {counts_of(data)}, want {want['counts']}")


def check_nrrd(path, want):
    data, header = nrrd.read(path)  # pynrrd: axis order as in the file (x fastest -> index 0)
    expect(header["space"] == "left-posterior-superior", f"space {header['space']}")
    expect(header["encoding"] == "gzip", f"encoding {header['encoding']}")
    expect(list(data.shape) == want["dims"], f"shape {data.shape}, want {want['dims']}")
    directions = np.asarray(header["space directions"], dtype=float)
    expect(np.abs(directions - np.asarray(want["directions"])).max() <= 1e-6,
           f"space directions {directions.tolist()}, want {want['directions']}")
    origin = np.asarray(header["space origin"], dtype=float)
    expect(np.abs(origin - np.asarray(want["origin"])).max() <= 1e-6, f"origin {origin}, want {want['origin']}")
    expect(counts_of(data) == want["counts"], f"counts {counts_of(data)}, want {want['counts']}")
    for i, s in enumerate(want["segments"]):
        p = f"Segment{i}_"
        for key in ("Name", "Color", "LabelValue", "Layer", "Extent", "ID", "Tags"):
            expect(p + key in header, f"{p + key} missing")
        if p + "Name" not in header:
            continue
        expect(header[p + "Name"] == s["name"], f"{p}Name {header[p + 'Name']!r}, want {s['name']!r}")
        colour = [float(c) for c in header[p + "Color"].split()]
        expect(np.abs(np.asarray(colour) - np.asarray(s["colour"])).max() <= 1e-5,
               f"{p}Color {colour}, want {s['colour']}")
        expect(int(header[p + "LabelValue"]) == s["label"], f"{p}LabelValue {header[p + 'LabelValue']}")
        expect(header[p + "Layer"] == "0", f"{p}Layer {header[p + 'Layer']}")
        # The extent is the box of the segment's voxels, inclusive, as Slicer writes it.
        where = np.argwhere(data == s["label"])
        box = " ".join(f"{where[:, a].min()} {where[:, a].max()}" for a in range(3)) if len(where) else "0 -1 0 -1 0 -1"
        expect(header[p + "Extent"] == box, f"{p}Extent {header[p + 'Extent']}, want {box}")
        tags = header[p + "Tags"]
        expect(s["type_code"] in tags, f"{p}Tags {tags!r} lacks {s['type_code']!r}")


def frames_of(seg):
    out = []
    for item in seg.PerFrameFunctionalGroupsSequence:
        number = int(item.SegmentIdentificationSequence[0].ReferencedSegmentNumber)
        position = [float(v) for v in item.PlanePositionSequence[0].ImagePositionPatient]
        source = None
        if "DerivationImageSequence" in item:
            source = str(item.DerivationImageSequence[0].SourceImageSequence[0].ReferencedSOPInstanceUID)
        out.append((number, position, source))
    return out


def check_seg(path, want):
    seg = hd.seg.segread(path)  # highdicom parses and checks the SEG's structure
    expect(seg.SOPClassUID == "1.2.840.10008.5.1.4.1.1.66.4", f"SOP class {seg.SOPClassUID}")
    expect(seg.SegmentationType == "BINARY", f"type {seg.SegmentationType}")
    expect(str(seg.FrameOfReferenceUID) == want["frame_of_reference"], "frame of reference")
    expect(str(seg.StudyInstanceUID) == want["study"], "study")
    series = [str(s.SeriesInstanceUID) for s in seg.ReferencedSeriesSequence] if "ReferencedSeriesSequence" in seg else []
    expect(series == [want["series"]], f"referenced series {series}, want {want['series']}")
    numbers = list(seg.segment_numbers)
    expect(numbers == [s["number"] for s in want["segments"]], f"segments {numbers}")
    for s in want["segments"]:
        d = seg.get_segment_description(s["number"])
        expect(d.segment_label == s["name"], f"label {d.segment_label!r}, want {s['name']!r}")
        expect(d.segmented_property_type.value == s["type_code"], f"type {d.segmented_property_type.value}")
        expect(d.segmented_property_category.value == s["category_code"],
               f"category {d.segmented_property_category.value}")
        expect(d.algorithm_type.value == s["algorithm"], f"algorithm {d.algorithm_type.value}")
    pixels = seg.pixel_array
    if pixels.ndim == 2:
        pixels = pixels[None]
    frames = frames_of(seg)
    counts = {}
    for (number, position, source), frame in zip(frames, pixels):
        counts[str(number)] = counts.get(str(number), 0) + int(np.count_nonzero(frame))
    expect(counts == want["counts"], f"voxels per segment {counts}, want {want['counts']}")
    # Each frame at the position and source image of the slice it came from.
    got = sorted((n, [round(v, 3) for v in p], s) for n, p, s in frames)
    exp = sorted((f["segment"], [round(v, 3) for v in f["position"]], f.get("source")) for f in want["frames"])
    expect(got == exp, f"frames differ:\n got {got[:4]}...\nwant {exp[:4]}...")
    if "labels_raw" in want:  # voxel for voxel: each frame's pixels where its slice has them
        x, y, z = want["dims"]
        labels = np.fromfile(want["labels_raw"], dtype=np.uint8).reshape(z, y, x)
        slice_at = {(f["segment"], tuple(round(v, 3) for v in f["position"])): f["slice"] for f in want["frames"]}
        rebuilt = np.zeros_like(labels)
        for (number, position, _), frame in zip(frames, pixels):
            k = slice_at.get((number, tuple(round(v, 3) for v in position)))
            if k is not None:
                rebuilt[k][frame != 0] = number
        expect((rebuilt == labels).all(), f"{int((rebuilt != labels).sum())} voxels differ from the label map")


def check_source(path, folder):
    """The SEG references the real series: each frame's source image is the file at its position."""
    seg = hd.seg.segread(path)
    by_uid = {}
    for name in os.listdir(folder):
        ds = pydicom.dcmread(os.path.join(folder, name), stop_before_pixels=True)
        by_uid[str(ds.SOPInstanceUID)] = ds
    any_ds = next(iter(by_uid.values()))
    series = [str(s.SeriesInstanceUID) for s in seg.ReferencedSeriesSequence]
    expect(series == [str(any_ds.SeriesInstanceUID)], f"referenced series {series}")
    referenced = {str(i.ReferencedSOPInstanceUID) for i in seg.ReferencedSeriesSequence[0].ReferencedInstanceSequence}
    expect(referenced == set(by_uid), f"{len(referenced)} instances referenced, the series has {len(by_uid)}")
    expect(str(seg.FrameOfReferenceUID) == str(any_ds.FrameOfReferenceUID), "frame of reference")
    expect(str(seg.PatientID) == str(any_ds.PatientID), "patient ID differs from the source's")
    expect(str(seg.StudyInstanceUID) == str(any_ds.StudyInstanceUID), "study differs from the source's")
    frames = frames_of(seg)
    expect(len(frames) > 0, "no frames")
    for number, position, source in frames:
        src = by_uid.get(source)
        expect(src is not None, f"frame references {source}, not in the series")
        if src is None:
            continue
        diff = max(abs(a - float(b)) for a, b in zip(position, src.ImagePositionPatient))
        expect(diff <= 1e-3, f"frame at {position} references the image at {list(src.ImagePositionPatient)}")
    print(f"{len(frames)} frames, each on its source image; {len(referenced)} instances referenced")


mode, path = sys.argv[1], sys.argv[2]
if mode == "source":
    check_source(path, sys.argv[3])
else:
    with open(sys.argv[3]) as f:
        want = json.load(f)
    {"nifti": check_nifti, "nrrd": check_nrrd, "seg": check_seg}[mode](path, want)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
