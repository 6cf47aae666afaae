"""A PET report's ROI values are SUVbw: checks the TID 1500 SR written by `voxray-cli
export-sr` on the pet-sphere phantom against SUVbw computed here with pydicom (the QIBA rule
of tests/dicom/suv_pydicom.py) from the files' pixels.

usage: check_sr_suv.py REPORT.dcm PET_FOLDER  (the report: --rect 14:14:16,33:33:16)"""
import sys
from pathlib import Path

try:
    import highdicom as hd
    import numpy as np
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "dicom"))
import suv_pydicom  # noqa: E402  (its QIBA rule)

report_path, folder = sys.argv[1], Path(sys.argv[2])
images = [pydicom.dcmread(p) for p in sorted(folder.glob("*.dcm"))]
images.sort(key=lambda d: float(d.ImagePositionPatient[2]))
factor = suv_pydicom.suv_factor(images)

s = images[16]
bq = s.pixel_array.astype(float) * float(s.RescaleSlope) + float(s.RescaleIntercept)
values = bq[14:34, 14:34] * factor  # rows and columns 14..33, both ends included
expected = {"Mean": values.mean(), "Standard Deviation": values.std(ddof=1),
            "Minimum": values.min(), "Maximum": values.max()}

ds = pydicom.dcmread(report_path)
sr = hd.sr.EnhancedSR.from_dataset(ds)
(group,) = sr.content.get_image_measurement_groups()
failures, seen = [], set()
for m in group.get_measurements():
    if m.name.value == "42798000":
        continue
    d = m.derivation.meaning
    seen.add(d)
    if (m.name.value, m.unit.value) != ("126401", "g/ml{SUVbw}"):
        failures.append(f"{d}: {m.name.value} {m.unit.value}, not SUVbw in g/ml{{SUVbw}}")
    # 1e-6 relative: the SR's 9 digits and the factor's double rounding, far below the
    # difference a wrong decay time would make.
    if abs(float(m.value) - expected[d]) > 1e-6 * abs(expected[d]):
        failures.append(f"{d}: {m.value} != {expected[d]} SUVbw")
if seen != set(expected):
    failures.append(f"values {seen}")
if failures:
    sys.exit("\n".join(failures))
print(f"PET ROI in SUVbw (factor {factor:.8g} g/mL per Bq/mL): mean {expected['Mean']:.6g}")
