#!/usr/bin/env python3
"""Writes the voxels of make-ct400.sh's series as one little-endian int16 raw in HU, for
VTK's bench (vtk_volume_bench.py reads raw volumes only) and for Voxray on the very same
voxels. Slices in the series' file order (make-ct400.sh names them bottom to top), x fastest.
DCMTK's dcmdump extracts each slice's pixel data (+W); numpy applies the rescale. Needs the
venv of ../shared/peers/README.md (numpy) and dcmtk. Never writes into the shared data.

usage: ct400-raw.py CT400_DIR OUT.raw
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

src, out_path = sys.argv[1], sys.argv[2]
if "/shared/data" in os.path.abspath(out_path):
    sys.exit("refusing to write into the shared data: " + out_path)
files = sorted(glob.glob(os.path.join(src, "ct400.*.dcm")))
if len(files) != 400:
    sys.exit(f"{src}: expected the 400 slices of make-ct400.sh, found {len(files)}")


def tag(f, t):
    text = subprocess.run(["dcmdump", "+P", t, f], capture_output=True, text=True, check=True)
    return float(re.search(r"\[([^\]]*)\]", text.stdout).group(1).strip("\x00 "))


with tempfile.TemporaryDirectory() as tmp, open(out_path, "wb") as out:
    for f in files:
        subprocess.run(["dcmdump", "-q", "+W", tmp, f], stdout=subprocess.DEVNULL, check=True)
        raw = os.path.join(tmp, os.path.basename(f) + ".0.raw")
        stored = np.fromfile(raw, "<i2")
        os.remove(raw)
        if stored.size != 512 * 512:
            sys.exit(f"{f}: expected 512x512 16-bit pixels, got {stored.size} values")
        hu = stored.astype(np.float64) * tag(f, "0028,1053") + tag(f, "0028,1052")
        out.write(np.clip(np.rint(hu), -32768, 32767).astype("<i2").tobytes())
print(out_path, "512x512x400 int16 LE HU, spacing 1,1,1 mm")
