#!/usr/bin/env python3
"""The import graph between Voxray's layers: which layer's files include which layer's
headers, counted. Each layer may include only the layers below it (docs/architecture.md);
an arrow up or sideways is printed with "UP" and makes the exit status 1. The build's
targets refuse most such includes already (a header not on a target's include path does
not compile); this also catches one that reaches a lower layer's folder by a relative path.

usage: scripts/import_graph.py [--quiet]   (from anywhere in the checkout)
"""
import collections
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Folder -> layer, and each layer's rank: a file may include a header of a lower rank.
LAYERS = {'io/core': 'core', 'io/pacs': 'pacs', 'io': 'io', 'kernels': 'kernels',
          'engine/lab': 'lab', 'engine': 'engine', 'ui/study': 'study', 'ui/widgets': 'widgets',
          'app/cli': 'cli', 'app/mpi': 'mpi', 'app': 'app'}
# mpi (voxray-mpi) sits above cli: it reuses the CLI's INPUT and render flags.
RANK = {'core': 0, 'io': 1, 'kernels': 1, 'pacs': 2, 'engine': 2, 'lab': 3, 'study': 4,
        'widgets': 5, 'cli': 6, 'app': 6, 'mpi': 7}
SOURCES = ('.h', '.hpp', '.inl', '.cl', '.cpp')


def layer_of(rel):
    for folder in sorted(LAYERS, key=len, reverse=True):
        if rel.startswith(folder + '/'):
            return LAYERS[folder]
    return None


def files():
    for folder in LAYERS:
        for d, _, names in os.walk(os.path.join(ROOT, folder)):
            for n in names:
                if n.endswith(SOURCES):
                    yield os.path.relpath(os.path.join(d, n), ROOT)


def main():
    owners = collections.defaultdict(set)  # an include name -> the layers with such a header
    for rel in files():
        if rel.endswith('.cpp'):
            continue
        owners[os.path.basename(rel)].add(layer_of(rel))
        m = re.search(r'include/(voxray/.*)$', rel) or re.search(r'kernels/(.*)$', rel)
        if m:
            owners[m.group(1)].add(layer_of(rel))
    edges = collections.Counter()
    for rel in set(files()):
        src = layer_of(rel)
        with open(os.path.join(ROOT, rel), errors='replace') as f:
            for line in f:
                m = re.match(r'\s*#\s*include\s*["<]([^">]+)[">]', line)
                if not m:
                    continue
                name = m.group(1)
                targets = owners.get(name) or owners.get(os.path.basename(name)) or set()
                if src in targets:
                    continue  # a header of its own layer (or one of the same name)
                for t in targets:
                    edges[(src, t)] += 1
    up = False
    for (a, b), n in sorted(edges.items()):
        bad = RANK[b] >= RANK[a]
        up |= bad
        if bad or '--quiet' not in sys.argv:
            print(f'{a:8s} -> {b:8s} {n:4d}{"  UP" if bad else ""}')
    return 1 if up else 0


if __name__ == '__main__':
    sys.exit(main())
