"""Reads a Key Object Selection written by `voxray-cli key-images` back with highdicom and
checks that it references the source files of the chosen slices (sorted by position, as
Voxray's k), in the order given, with the description.

usage: check_kos.py KOS.dcm SOURCE_FOLDER SLICES DESCRIPTION  (SLICES: 10,20,5)"""
import sys
from pathlib import Path

try:
    import highdicom as hd
    import numpy as np
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")

kos_path, source, slices, description = sys.argv[1], Path(sys.argv[2]), sys.argv[3], sys.argv[4]
images = [pydicom.dcmread(p, stop_before_pixels=True) for p in sorted(source.iterdir())
          if p.suffix == ".dcm"]
normal = np.cross(np.array(images[0].ImageOrientationPatient[:3], float),
                  np.array(images[0].ImageOrientationPatient[3:], float))
images.sort(key=lambda d: float(np.dot(normal, np.array(d.ImagePositionPatient, float))))
wanted = [images[int(k)].SOPInstanceUID for k in slices.split(",")]

ds = pydicom.dcmread(kos_path)
kos = hd.ko.KeyObjectSelectionDocument.from_dataset(ds)
refs = [r.ReferencedSOPSequence[0].ReferencedSOPInstanceUID for r in kos.content.get_references()]
failures = []
if refs != wanted:
    failures.append(f"references {refs} != {wanted}")
texts = [c.TextValue for c in ds.ContentSequence if c.ValueType == "TEXT"]
if texts != [description]:
    failures.append(f"description {texts}")
if ds.StudyInstanceUID != images[0].StudyInstanceUID:
    failures.append("not in the images' study")
evidence = [r.ReferencedSOPInstanceUID for e in ds.CurrentRequestedProcedureEvidenceSequence
            for s in e.ReferencedSeriesSequence for r in s.ReferencedSOPSequence]
if sorted(evidence) != sorted(wanted):
    failures.append(f"evidence {evidence}")
if failures:
    sys.exit("\n".join(failures))
print(f"KOS references slices {slices} of the series")
