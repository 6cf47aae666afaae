"""SUVbw of a PET series computed independently of Voxray: pydicom reads the attributes and
the pixels, the QIBA vendor-neutral rule is written out here again. Prints the scale factor
(g/mL per Bq/mL) and the SUV of the brightest voxel."""
import datetime
import glob
import sys

import pydicom


def when(date, time):
    whole, _, fraction = time.partition(".")
    t = datetime.datetime.strptime(date + whole.ljust(6, "0"), "%Y%m%d%H%M%S")
    return t + datetime.timedelta(microseconds=int(fraction.ljust(6, "0")[:6] or 0))


def suv_factor(images):
    """The SUVbw factor (g/mL per Bq/mL) of a PET series' datasets by the QIBA rule."""
    first = images[0]
    assert first.Units == "BQML", first.Units
    series = when(first.SeriesDate, first.SeriesTime)
    acquired = min(when(d.AcquisitionDate, d.AcquisitionTime) for d in images)
    scan = series
    if acquired < series:
        # A series made after the scan: GE keeps the scan's start in a private DateTime.
        try:
            ge = first.private_block(0x0009, "GEMS_PETD_01")[0x0D].value
            scan = datetime.datetime.strptime(str(ge)[:14], "%Y%m%d%H%M%S")
        except KeyError:
            scan = acquired
    drug = first.RadiopharmaceuticalInformationSequence[0]
    if "RadiopharmaceuticalStartDateTime" in drug:
        injected = datetime.datetime.strptime(drug.RadiopharmaceuticalStartDateTime[:14],
                                              "%Y%m%d%H%M%S")
    else:
        injected = when(first.SeriesDate, drug.RadiopharmaceuticalStartTime)
        if injected > scan:
            injected -= datetime.timedelta(days=1)
    dose = float(drug.RadionuclideTotalDose)
    if first.DecayCorrection == "START":
        dose *= 2.0 ** (-(scan - injected).total_seconds() / float(drug.RadionuclideHalfLife))
    return float(first.PatientWeight) * 1000.0 / dose


def main(folder):
    images = [pydicom.dcmread(f) for f in sorted(glob.glob(folder + "/*.dcm"))]
    factor = suv_factor(images)
    brightest = max(float(d.pixel_array.max()) * float(d.RescaleSlope) + float(d.RescaleIntercept)
                    for d in images)
    print(repr(factor), repr(brightest * factor))


if __name__ == "__main__":
    main(sys.argv[1])
