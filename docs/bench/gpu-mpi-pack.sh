#!/usr/bin/env bash
# Packs Debian's Open MPI runtime beside the lean GPU build (build-gpu/) so voxray-mpi runs on
# the device machine, whose image has no MPI: orterun, Open MPI's and PMIx's plugins and help
# texts under build-gpu/mpi (relocated there through OPAL_PREFIX / PMIX_INSTALL_PREFIX, see
# gpu-mpi-env.sh), the libraries voxray-mpi and orterun link into build-gpu/lib (the carried
# loader's library path). Run here, from the repository root, after building voxray-mpi.
set -euo pipefail
root=build-gpu/mpi
lib=build-gpu/lib
multi=/usr/lib/x86_64-linux-gnu
rm -rf "$root"
mkdir -p "$root/bin" "$root/lib/x86_64-linux-gnu/openmpi/lib" "$root/share" "$root/pmix2/lib"
cp -L /usr/bin/orterun "$root/bin/"
cp -a $multi/openmpi/lib/openmpi3 "$root/lib/x86_64-linux-gnu/openmpi/lib/"
cp -a /usr/share/openmpi "$root/share/"
cp -a $multi/pmix2/lib/pmix "$root/pmix2/lib/"
cp -a $multi/pmix2/share "$root/pmix2/" 2>/dev/null || true
# Every library the programs and the plugins link that the carried set lacks.
for f in build-gpu/bin/voxray-mpi "$root/bin/orterun" $multi/pmix2/lib/libpmix.so.2 \
  "$root"/lib/x86_64-linux-gnu/openmpi/lib/openmpi3/*.so "$root"/pmix2/lib/pmix/*.so; do
  ldd "$f" 2>/dev/null | awk '/=> \//{print $3}'
done | sort -u | while read -r so; do
  [[ -e $lib/$(basename "$so") ]] || cp -L "$so" "$lib/"
done
cp -L $multi/pmix2/lib/libpmix.so.2 "$lib/"
du -sh "$root" "$lib"
