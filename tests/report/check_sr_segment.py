"""A segment's SUVpeak in the SR (issue 36): checks the TID 1501 group `voxray-cli export-sr
--labels` wrote for the pet-sphere phantom's sphere (segmented at 10000 ... 30000 Bq/mL)
against values computed here with pydicom from the files: SUVbw as tests/dicom/suv_pydicom.py
computes it (QIBA), the sphere's voxels and volume, and the SUVpeak, which for the sphere's
uniform activity is the sphere's SUV. The concept: SUVbw (126401, DCM) with the derivation
Peak Value Within ROI (126031, DCM; CID 7464), unit g/ml{SUVbw}. The CSV holds it too.

usage: check_sr_segment.py REPORT.dcm PET_FOLDER CSV"""
import csv
import sys
from pathlib import Path

try:
    import numpy as np
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "dicom"))
import suv_pydicom  # noqa: E402  (its QIBA rule)

report_path, folder, csv_path = sys.argv[1], Path(sys.argv[2]), sys.argv[3]
images = [pydicom.dcmread(p) for p in sorted(folder.glob("*.dcm"))]
first = images[0]
factor = suv_pydicom.suv_factor(images)

bq = np.stack([d.pixel_array.astype(float) * float(d.RescaleSlope) + float(d.RescaleIntercept)
               for d in images])
inside = (bq >= 10000) & (bq <= 30000)
suv = bq[inside] * factor
row_mm, col_mm = (float(x) for x in first.PixelSpacing)
voxel_mm3 = row_mm * col_mm * float(first.SliceThickness)
expected = {"peak": suv.max(), "Mean": suv.mean(), "Minimum": suv.min(), "Maximum": suv.max(),
            "volume": inside.sum() * voxel_mm3}
failures = []


def code(item, attr="ConceptNameCodeSequence"):
    seq = getattr(item, attr, None)
    return (seq[0].CodeValue, seq[0].CodingSchemeDesignator) if seq else None


def walk(item):
    for child in getattr(item, "ContentSequence", []):
        yield child
        yield from walk(child)


ds = pydicom.dcmread(report_path)
nums = [i for i in walk(ds) if i.ValueType == "NUM"]
seen = {}
for n in nums:
    value = float(n.MeasuredValueSequence[0].NumericValue)
    unit = code(n.MeasuredValueSequence[0], "MeasurementUnitsCodeSequence")
    # The derivation modifier (121401, DCM): its coded value names the statistic.
    derivations = [c.ConceptCodeSequence[0] for c in getattr(n, "ContentSequence", [])
                   if code(c) == ("121401", "DCM")]
    if code(n) == ("118565006", "SCT"):
        seen["volume"] = value
        if unit != ("mm3", "UCUM"):
            failures.append(f"volume unit {unit}")
    elif code(n) == ("126401", "DCM"):
        if unit != ("g/ml{SUVbw}", "UCUM"):
            failures.append(f"SUVbw unit {unit}")
        if len(derivations) != 1:
            failures.append(f"an SUVbw value with {len(derivations)} derivations")
            continue
        d = derivations[0]
        seen["peak" if (d.CodeValue, d.CodingSchemeDesignator) == ("126031", "DCM")
             else d.CodeMeaning] = value
for key in ("peak", "Mean", "Minimum", "Maximum", "volume"):
    if key not in seen:
        failures.append(f"no {key} in the report ({sorted(seen)})")
    # 1e-6 relative: the SR's 9 digits and the factor's double rounding.
    elif abs(seen[key] - expected[key]) > 1e-6 * abs(expected[key]):
        failures.append(f"{key}: {seen[key]} != {expected[key]}")

rows = [r for r in csv.DictReader(open(csv_path)) if r["quantity"] == "suv_peak"]
if len(rows) != 1 or rows[0]["unit"] != "SUVbw" or \
        abs(float(rows[0]["value"]) - expected["peak"]) > 1e-5 * expected["peak"]:
    failures.append(f"CSV suv_peak rows {rows}")

if failures:
    sys.exit("\n".join(failures))
print(f"segment SUVpeak {seen['peak']:.6g} SUVbw (pydicom {expected['peak']:.6g}), "
      f"volume {seen['volume']:.6g} mm3, {int(inside.sum())} voxels")
