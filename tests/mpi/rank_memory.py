"""A voxray-mpi rank holds its slab, not the whole volume (tests/mpi/CMakeLists.txt).

rank_memory.py MPIEXEC VOXRAY_MPI OUTDIR NP [MPI_FLAGS...]

Writes a 512x512x512 int16 raw volume (V = 256 MiB) and a 64x64x16 one, runs voxray-mpi on NP
ranks on each (one 64x48 dvr frame, PoCL) and reads each rank's peak resident memory from its
own report (getrusage in the rank: ru_maxrss) and the slices it held (its range and apron).
What the big volume adds to a rank's peak over the small one's run (the same ranks, libraries,
PoCL and kernels) is what the rank holds for it:
  its slab: the held slices (V/NP and 4 apron slices on each inner side: 66-68 MiB at NP=4);
  the empty-space cells, which span the whole volume (the kernels address them globally):
  12 bytes per 4x4x4 cell (min/max on the host, 8 bytes of leap data on the device, which
  PoCL keeps in host memory): V * 12 / 128 = 24 MiB here.
Bound: 0.75 to 1 times that, plus 24 MiB of slack above (the frame's image buffers, PoCL's and
the allocator's own; measured 5 MiB over at NP=4). Below 0.75 the slab would not be in memory
(the test would measure nothing); a rank holding the whole volume's size, as before, adds
V + the cells (280 MiB at NP=4, against a bound of 116 MiB).
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
    held = {int(k): int(b) - int(a) + 1
            for k, a, b in re.findall(r"rank (\d+): .*\(held (\d+)-(\d+), read alone\)",
                                      run.stdout)}
    if len(found) != np_ranks or len(held) != np_ranks:
        sys.exit("expected %d ranks' peak resident memory and slabs read alone, found %d and %d"
                 % (np_ranks, len(found), len(held)))
    return {int(k): int(v) for k, v in found.items()}, held


big, small = (512, 512, 512), (64, 64, 16)
big_path, small_path = os.path.join(out, "big.raw"), os.path.join(out, "small.raw")
if not os.path.exists(big_path) or os.path.getsize(big_path) != 2 * big[0] * big[1] * big[2]:
    write(big_path, big)
write(small_path, small)
volume_mib = 2 * big[0] * big[1] * big[2] / 2**20
share = volume_mib / np_ranks
(base, _), (peak, held) = peaks(small_path, small), peaks(big_path, big)
slice_mib = 2 * big[0] * big[1] / 2**20
cells_mib = volume_mib * 12 / 128
failed = False
for rank in sorted(peak):
    added = peak[rank] - base[rank]
    expected = held[rank] * slice_mib + cells_mib
    ok = 0.75 * expected <= added <= expected + 24
    failed = failed or not ok
    print("rank %d: peak %d MiB with the %.0f MiB volume, %d MiB with the small one: %d MiB "
          "added for a slab of %d slices (%.0f MiB) and cells of %.0f MiB (V/%d: %.0f MiB); "
          "bound %.0f-%.0f MiB%s"
          % (rank, peak[rank], volume_mib, base[rank], added, held[rank], held[rank] * slice_mib,
             cells_mib, np_ranks, share, 0.75 * expected, expected + 24,
             "" if ok else "  <-- out of bound"))
sys.exit(1 if failed else 0)
