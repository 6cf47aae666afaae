"""A voxray-mpi rank holds its slab, not the whole volume (tests/mpi/CMakeLists.txt).

rank_memory.py MPIEXEC VOXRAY_MPI OUTDIR NP [MPI_FLAGS...]

Writes a 512x512x512 int16 raw volume (256 MiB) and a 64x64x16 one, runs voxray-mpi on NP ranks
on each (one 64x48 dvr frame, PoCL) and reads each rank's peak resident memory from its own
report (getrusage in the rank: ru_maxrss). What the big volume adds to a rank's peak over the
small one's run (the same ranks, libraries, PoCL and kernels) is its slab: V/NP and an apron of
4 slices (2 MiB) on each inner side. Bound: between 0.5 and 1.5 times V/NP for every rank.
Below, the slab is not in memory at all (the test would measure nothing); above 1.5 V/NP
(384 MiB of 256 MiB at NP=4 was the whole volume) a second copy or the whole volume is held.
The slack above 1: the slab's read may hold one more slab-sized buffer for a moment (import
converts in place here), the empty-space cells and allocator noise of a few MiB.
"""
import os
import re
import subprocess
import sys

import numpy as np

mpiexec, voxray_mpi, out, np_ranks = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
mpi_flags = sys.argv[5:]
os.makedirs(out, exist_ok=True)


def write(path, n):
    """A ball of 1000 in -1000, written slice by slice (no whole volume in this process)."""
    yy, xx = np.mgrid[0:n[1], 0:n[0]]
    with open(path, "wb") as f:
        for z in range(n[2]):
            r = np.sqrt(((xx - n[0] / 2) / (0.4 * n[0])) ** 2 + ((yy - n[1] / 2) / (0.4 * n[1])) ** 2
                        + ((z - n[2] / 2) / (0.4 * n[2])) ** 2)
            f.write(np.where(r < 1.0, 1000, -1000).astype("<i2").tobytes())


def peaks(path, n):
    cmd = [mpiexec] + mpi_flags + ["-n", str(np_ranks), voxray_mpi, path, "--raw-dims",
                                   "%d,%d,%d" % n, "--raw-type", "i16", "--raw-endian", "little",
                                   "--mode", "dvr", "--preset", "CT-Bone", "--size", "64x48",
                                   "-o", os.path.join(out, "frame.png")]
    run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         timeout=240)
    print(run.stdout)
    if run.returncode != 0:
        sys.exit("voxray-mpi failed (%d)" % run.returncode)
    found = dict(re.findall(r"rank (\d+): part .*peak resident (\d+) MiB", run.stdout))
    if len(found) != np_ranks:
        sys.exit("expected %d ranks' peak resident memory, found %d" % (np_ranks, len(found)))
    return {int(k): int(v) for k, v in found.items()}


big, small = (512, 512, 512), (64, 64, 16)
big_path, small_path = os.path.join(out, "big.raw"), os.path.join(out, "small.raw")
if not os.path.exists(big_path) or os.path.getsize(big_path) != 2 * big[0] * big[1] * big[2]:
    write(big_path, big)
write(small_path, small)
volume_mib = 2 * big[0] * big[1] * big[2] / 2**20
share = volume_mib / np_ranks
base, held = peaks(small_path, small), peaks(big_path, big)
failed = False
for rank in sorted(held):
    added = held[rank] - base[rank]
    ok = 0.5 * share <= added <= 1.5 * share
    failed = failed or not ok
    print("rank %d: peak %d MiB with the %.0f MiB volume, %d MiB with the small one: %d MiB "
          "added, %.2f of V/%d (%.0f MiB; bound 0.5-1.5)%s"
          % (rank, held[rank], volume_mib, base[rank], added, added / share, np_ranks, share,
             "" if ok else "  <-- out of bound"))
sys.exit(1 if failed else 0)
