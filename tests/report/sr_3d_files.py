"""What the SCOORD3D checks share: the source images in slice order, a voxel's LPS position
from their headers (PS3.3 C.7.6.2.1.1), and the report's SCOORD3D items, after highdicom has
read the report as a Comprehensive 3D SR."""
import sys
from pathlib import Path

try:
    import highdicom as hd
    import numpy as np
    import pydicom
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with pydicom and highdicom)")


def source_images(source):
    """The folder's images sorted along their normal."""
    images = [pydicom.dcmread(p) for p in sorted(Path(source).iterdir()) if p.suffix == ".dcm"]
    normal = np.cross(np.array(images[0].ImageOrientationPatient[:3], float),
                      np.array(images[0].ImageOrientationPatient[3:], float))
    images.sort(key=lambda d: float(np.dot(normal, np.array(d.ImagePositionPatient, float))))
    return images


def lps(images, i, j, k):
    """Column index i along the row direction, row j, k a whole slice; in mm."""
    assert k == int(k), "the test's points lie on slices"
    d = images[int(k)]
    o = np.array(d.ImageOrientationPatient, float)
    r_mm, c_mm = (float(x) for x in d.PixelSpacing)
    return np.array(d.ImagePositionPatient, float) + i * c_mm * o[:3] + j * r_mm * o[3:]


def scoord3d_items(report_path):
    """The report's SCOORD3D content items, anywhere in its tree."""
    ds = pydicom.dcmread(report_path)
    hd.sr.Comprehensive3DSR.from_dataset(ds)  # highdicom reads it as its IOD

    def walk(item):
        for child in getattr(item, "ContentSequence", []):
            yield child
            yield from walk(child)

    return [i for i in walk(ds) if i.ValueType == "SCOORD3D"]
