"""Writes a raw uint8 label map (x fastest, then y, then z) of DIMS with a box per label, and
the boxes as JSON for check_sr_seg.py. Labels 1 and 3: label 3 is the second segment, so its
number in a DICOM SEG differs from its label. Odd slice counts put each centre on a slice.

usage: make_label_boxes.py NX NY NZ LABELS.raw BOXES.json"""
import json
import sys

try:
    import numpy as np
except ImportError as e:
    sys.exit(f"{e}: run scripts/bootstrap (it makes the .venv with numpy)")

nx, ny, nz = (int(x) for x in sys.argv[1:4])
boxes = {"1": [100, 139, 200, 229, 10, 18], "3": [300, 319, 250, 259, 41, 59]}  # i0 i1 j0 j1 k0 k1
labels = np.zeros((nz, ny, nx), np.uint8)
for label, (i0, i1, j0, j1, k0, k1) in boxes.items():
    labels[k0:k1 + 1, j0:j1 + 1, i0:i1 + 1] = int(label)
labels.tofile(sys.argv[4])
json.dump(boxes, open(sys.argv[5], "w"))
