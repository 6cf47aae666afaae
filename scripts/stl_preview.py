#!/usr/bin/env python3
"""A picture of an STL for the README, made without Voxray: trimesh reads the file, numpy
splats every triangle's centroid into a z-buffer (front view, patient anterior facing the
viewer) and shades it by its normal; Pillow writes the PNG. An independent look at what a
printer or CAD program gets, not a renderer.

Usage: .venv/bin/python scripts/stl_preview.py IN.stl OUT.png [SIZE]
"""
import sys

import numpy as np
import trimesh
from PIL import Image


def main():
    src, dst = sys.argv[1], sys.argv[2]
    size = int(sys.argv[3]) if len(sys.argv) > 3 else 800
    mesh = trimesh.load(src, force="mesh")
    tri = mesh.triangles  # (n, 3, 3), LPS mm: x left, y posterior, z superior
    centres = tri.mean(axis=1)
    normals = mesh.face_normals
    # Seen from the front: screen x = patient right on the image left (x), screen y = -z,
    # depth = y (anterior, smaller y, is nearer).
    lo, hi = centres.min(axis=0), centres.max(axis=0)
    scale = (size - 20) / max(hi[0] - lo[0], hi[2] - lo[2])
    # A grid of barycentric samples per triangle (15) so that big ones leave no holes.
    n = 4
    weights = np.array([[i, j, n - i - j] for i in range(n + 1) for j in range(n + 1 - i)],
                       dtype=float) / n
    pts = np.einsum("kj,njd->nkd", weights, tri).reshape(-1, 3)
    nrm = np.repeat(normals, len(weights), axis=0)
    margin_x = (size - (hi[0] - lo[0]) * scale) / 2
    px = ((pts[:, 0] - lo[0]) * scale + margin_x).astype(int)
    py = ((hi[2] - pts[:, 2]) * scale + 10).astype(int)
    depth = pts[:, 1]
    ok = (px >= 0) & (px < size) & (py >= 0) & (py < size)
    px, py, depth, nrm = px[ok], py[ok], depth[ok], nrm[ok]
    flat = py * size + px
    order = np.lexsort((depth, flat))  # nearest first within each pixel
    flat_sorted = flat[order]
    first = np.ones(len(order), dtype=bool)
    first[1:] = flat_sorted[1:] != flat_sorted[:-1]
    keep = order[first]
    light = np.array([0.3, -0.8, 0.5])
    light /= np.linalg.norm(light)
    shade = np.clip(nrm[keep] @ light, 0, 1) * 0.8 + 0.2
    bone = np.array([0.93, 0.86, 0.70])
    img = np.zeros((size * size, 3))
    img[flat[keep]] = shade[:, None] * bone
    img = img.reshape(size, size, 3)
    Image.fromarray((img * 255).astype(np.uint8)).save(dst)
    print(f"{len(mesh.faces)} triangles, watertight {mesh.is_watertight}, "
          f"extent {np.round(mesh.extents, 1)} mm -> {dst}")


if __name__ == "__main__":
    main()
