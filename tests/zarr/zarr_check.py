"""The independent side of Voxray's OME-Zarr tests, through zarr-python (pinned in
scripts/bootstrap's venv).

  zarr_check.py read OUT.ome.zarr EXPECT.json   checks what Voxray wrote: every level's values
      (level 0 against the raw int16 file the test wrote, each coarser level against a 2x2x2
      mean computed here from the level before, as zarr read it) and the multiscales metadata.
  zarr_check.py make OUT.ome.zarr VARIANT        writes an OME-Zarr the way other tools do, with
      OUT.expected.f64 (level 0's values, z, y, x C order) and OUT.expected.json (geometry in
      mm) beside it for the C++ test to compare with.
Exit 0 and one line "OK ..." when all is right; otherwise what differs, and exit 1.
"""
import json
import sys

import numpy as np
import numcodecs
import zarr
from zarr.codecs import BloscCodec, BytesCodec, GzipCodec, ZstdCodec


def halve(a):
    """2x2x2 mean; an odd last slice, row or column is averaged alone."""
    shape = tuple((n + 1) // 2 for n in a.shape)
    total = np.zeros(shape)
    count = np.zeros(shape)
    for dz in (0, 1):
        for dy in (0, 1):
            for dx in (0, 1):
                s = a[dz::2, dy::2, dx::2].astype(np.float64)
                total[: s.shape[0], : s.shape[1], : s.shape[2]] += s
                count[: s.shape[0], : s.shape[1], : s.shape[2]] += 1
    return total / count


def fail(message):
    print("FAIL " + message)
    sys.exit(1)


def read(path, expect_path):
    expect = json.load(open(expect_path))
    g = zarr.open_group(path, mode="r")
    if g.metadata.zarr_format != expect["zarr_format"]:
        fail(f"zarr_format {g.metadata.zarr_format}, expected {expect['zarr_format']}")
    attrs = dict(g.attrs)
    ms = attrs["ome"]["multiscales"] if expect["zarr_format"] == 3 else attrs["multiscales"]
    version = attrs["ome"]["version"] if expect["zarr_format"] == 3 else ms[0]["version"]
    if version != expect["ngff"]:
        fail(f"NGFF version {version}, expected {expect['ngff']}")
    m = ms[0]
    axes = [(a["name"], a["type"], a["unit"]) for a in m["axes"]]
    if axes != [("z", "space", "millimeter"), ("y", "space", "millimeter"), ("x", "space", "millimeter")]:
        fail(f"axes {axes}")
    if len(m["datasets"]) != len(expect["levels"]):
        fail(f"{len(m['datasets'])} datasets, expected {len(expect['levels'])}")
    previous = None
    for level, (d, e) in enumerate(zip(m["datasets"], expect["levels"])):
        t = {x["type"]: x for x in d["coordinateTransformations"]}
        # 1e-9 mm: JSON keeps doubles to 17 digits; both sides compute the same sums.
        if not np.allclose(t["scale"]["scale"], e["scale"], rtol=0, atol=1e-9):
            fail(f"level {level} scale {t['scale']['scale']}, expected {e['scale']}")
        if not np.allclose(t["translation"]["translation"], e["translation"], rtol=0, atol=1e-9):
            fail(f"level {level} translation {t['translation']['translation']}, expected {e['translation']}")
        a = g[d["path"]]
        if list(a.shape) != e["shape"]:
            fail(f"level {level} shape {a.shape}, expected {e['shape']}")
        if str(a.dtype) != expect["dtype"]:
            fail(f"level {level} dtype {a.dtype}, expected {expect['dtype']}")
        values = a[:]
        if level == 0:
            truth = np.fromfile(expect["raw"], dtype="<i2").reshape(values.shape)
            if not np.array_equal(values, truth):
                fail(f"level 0 differs from the source in {int((values != truth).sum())} voxels")
        else:
            # int16 levels round the mean half to even (C's nearbyint, numpy's rint).
            truth = np.rint(halve(previous)).astype(values.dtype)
            if not np.array_equal(values, truth):
                fail(f"level {level} differs from the 2x mean of level {level - 1} in "
                     f"{int((values != truth).sum())} voxels")
        previous = values
    print(f"OK zarr {zarr.__version__} read {len(m['datasets'])} levels")


def make(path, variant):
    # z, y, x; values and geometry per variant; units are converted to mm in expected.json.
    if variant == "v2-u16be-blosc-lz4-dot":
        fmt, shape, chunks = 2, (9, 20, 23), (4, 8, 8)
        z, y, x = np.indices(shape)
        values = ((x + 3 * y + 35 * z) % 4000).astype(">u2")
        unit, to_mm = "micrometer", 1e-3
        scale, translation = [1500.0, 400.0, 300.0], [1000.0, -2000.0, 500.0]
        arr = dict(dtype=">u2", compressors=numcodecs.Blosc(cname="lz4", shuffle=numcodecs.Blosc.SHUFFLE),
                   chunk_key_encoding={"name": "v2", "separator": "."})
    elif variant == "v3-f32-zstd":
        fmt, shape, chunks = 3, (7, 11, 13), (3, 4, 5)
        z, y, x = np.indices(shape)
        values = ((x - y) * 0.5 + z).astype("float32")
        unit, to_mm = "millimeter", 1.0
        scale, translation = [2.5, 0.75, 0.5], [-30.0, 12.25, -7.5]
        arr = dict(dtype="float32", compressors=ZstdCodec(level=3))
    elif variant == "v2-i16-gzip-slash":
        fmt, shape, chunks = 2, (6, 10, 9), (4, 4, 4)
        z, y, x = np.indices(shape)
        values = (x * 100 - y * 37 + z * 11 - 1024).astype("<i2")
        unit, to_mm = "millimeter", 1.0
        scale, translation = [3.0, 1.0, 1.0], [0.0, 0.0, 0.0]
        arr = dict(dtype="<i2", compressors=numcodecs.GZip(level=5),
                   chunk_key_encoding={"name": "v2", "separator": "/"})
    elif variant == "v3-i16be-blosc":
        fmt, shape, chunks = 3, (5, 12, 10), (5, 5, 5)
        z, y, x = np.indices(shape)
        values = (x * 300 - y * 250 + z * 7000 - 3000).astype("int16")
        unit, to_mm = "centimeter", 10.0
        scale, translation = [0.2, 0.05, 0.05], [1.0, 2.0, 3.0]
        arr = dict(dtype="int16", serializer=BytesCodec(endian="big"),
                   compressors=BloscCodec(cname="zstd", clevel=3, shuffle="bitshuffle"))
    else:
        fail(f"unknown variant {variant}")
    g = zarr.open_group(path, mode="w", zarr_format=fmt)
    a = g.create_array("0", shape=shape, chunks=chunks, fill_value=0, **arr)
    a[:] = values
    axes = [{"name": n, "type": "space", "unit": unit} for n in ("z", "y", "x")]
    ms = {"axes": axes, "name": variant,
          "datasets": [{"path": "0", "coordinateTransformations": [
              {"type": "scale", "scale": scale}, {"type": "translation", "translation": translation}]}]}
    if fmt == 2:
        ms["version"] = "0.4"
        g.attrs["multiscales"] = [ms]
    else:
        g.attrs["ome"] = {"version": "0.5", "multiscales": [ms]}
    values.astype("<f8").tofile(path + ".expected.f64")
    json.dump({"dims": list(reversed(shape)),
               "spacing_mm": [s * to_mm for s in reversed(scale)],
               "origin_mm": [t * to_mm for t in reversed(translation)]},
              open(path + ".expected.json", "w"))
    print(f"OK wrote {variant}")


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[1] not in ("read", "make"):
        fail("usage: zarr_check.py read OUT.ome.zarr EXPECT.json | make OUT.ome.zarr VARIANT")
    (read if sys.argv[1] == "read" else make)(sys.argv[2], sys.argv[3])
