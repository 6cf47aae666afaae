"""Reads Voxray's mesh files with trimesh (an independent reader) and prints what it sees as
JSON, one object per file given: bounds, watertightness, volume, face count, colours and the
file's own header text or comments."""
import json
import sys

import numpy as np
import trimesh


def header_text(path):
    with open(path, "rb") as f:
        head = f.read(4096)
    if path.lower().endswith(".stl"):
        return head[:80].rstrip(b"\0 ").decode("ascii", "replace")
    if path.lower().endswith(".ply"):
        text = head.split(b"end_header")[0].decode("ascii", "replace")
        return "\n".join(l[8:] for l in text.splitlines() if l.startswith("comment "))
    return "\n".join(l[2:] for l in head.decode("ascii", "replace").splitlines() if l.startswith("# "))


def describe(path):
    loaded = trimesh.load(path, process=False)
    parts = list(loaded.geometry.values()) if isinstance(loaded, trimesh.Scene) else [loaded]
    for p in parts:
        p.merge_vertices()  # an STL is a triangle soup: weld it before asking if it is closed
    colours = []
    for p in parts:
        if path.lower().endswith(".obj"):
            colours.append([float(c) / 255.0 for c in p.visual.material.diffuse[:3]])
        elif path.lower().endswith(".ply"):
            colours += [list(map(int, c[:3])) for c in np.unique(p.visual.face_colors, axis=0)]
    merged = trimesh.util.concatenate(parts) if len(parts) > 1 else parts[0]
    return {
        "path": path,
        "parts": len(parts),
        "bounds": merged.bounds.tolist(),
        "watertight": all(bool(p.is_watertight) for p in parts),
        "volume": float(sum(p.volume for p in parts)),
        "faces": int(len(merged.faces)),
        "colours": colours,
        "header": header_text(path),
    }


print(json.dumps([describe(p) for p in sys.argv[1:]]))
