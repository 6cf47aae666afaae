# Sourced from the repository root by the GPU bench scripts (gpu-bench.sh,
# gpu-bench-bricks.sh): NVIDIA's OpenCL through a vendors file, the carried CLI (through
# the carried loader when it does not start as it is), the carried data and the cases the
# scripts share.
mkdir -p /tmp/vendors && echo /usr/lib/libnvidia-opencl.so.1 > /tmp/vendors/nvidia.icd
export OCL_ICD_VENDORS=/tmp/vendors
ldd --version | head -1
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
B="build-gpu/bin/voxray-cli"
if ! $B devices >/dev/null 2>&1; then
  B="build-gpu/lib/ld-linux-x86-64.so.2 --library-path build-gpu/lib build-gpu/bin/voxray-cli"
fi
$B devices
D=build-gpu/data
CT="$D/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big --raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI"
# A 512x512x400 CT made from the carried cranium (make_ct512.py), as V.
V="/tmp/ct512.raw --raw-dims 512,512,400 --raw-type i16 --raw-spacing 0.4785,0.4785,0.405"
make_ct512() {
  python3 docs/bench/make_ct512.py $D/raw/cranium-ct/cranium_256x256x108_s16le.raw /tmp/ct512.raw
}
