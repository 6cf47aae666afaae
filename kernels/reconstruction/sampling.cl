// Reconstruction of the volume at a point in voxel coordinates (voxel centres at
// integers), clamped to the edge. Options:
//   STORAGE_IMAGE 1: image3d_t (CL_SNORM_INT16) read texel by texel (GPUs: the texture
//                    cache), interpolated here as for buffers
//   STORAGE_IMAGE 0: a buffer of shorts (CPUs: PoCL samples a buffer about 3x faster
//                    than an image)
//   INTERP 0 nearest, 1 trilinear
//   SLABS k: the volume in k slabs along z (slabs.cl)
// Every function takes the frame parameters as P: the uber kernel reads INTERP there.
// sample_slab reads one slab (the whole volume when SLABS is 1) of extent dims.
#ifndef VOXRAY_SAMPLING_CL
#define VOXRAY_SAMPLING_CL

#include "variant.cl"

#if STORAGE_IMAGE
#define SLAB_TYPE __read_only image3d_t
__constant sampler_t vol_nearest =
    CLK_NORMALIZED_COORDS_FALSE | CLK_ADDRESS_CLAMP_TO_EDGE | CLK_FILTER_NEAREST;

// One stored voxel. CL_SNORM_INT16 holds v / 32767, so rint gives v back exactly (-32768
// reads as -32767). Interpolation is ours, not the sampler's: GPUs filter with 8-bit
// weights (NVIDIA: 1/256 steps), which put iso surfaces and gradients of int16 extremes
// hundreds of levels off the reference (docs/stability/README.md).
inline float voxel_at(SLAB_TYPE vol, int4 dims, int x, int y, int z) {
  return rint(read_imagef(vol, vol_nearest, (int4)(x, y, z, 0)).x * 32767.0f);
}
#else
#define SLAB_TYPE __global const short* restrict
inline float voxel_at(SLAB_TYPE vol, int4 dims, int x, int y, int z) {
  return (float)vol[((size_t)z * dims.y + y) * dims.x + x];
}
#endif

inline float sample_slab(SLAB_TYPE vol, int4 dims, __constant RaycastParams* P, float3 p) {
  int3 hi = dims.xyz - 1;
  if (!INTERP) {
    int3 i = clamp(convert_int3(floor(p + 0.5f)), (int3)(0), hi);
    return voxel_at(vol, dims, i.x, i.y, i.z);
  }
  float3 f0 = floor(p);
  float3 f = p - f0;
  int3 i0 = convert_int3(f0);
  int3 a = clamp(i0, (int3)(0), hi);
  int3 b = clamp(i0 + 1, (int3)(0), hi);
  float c000 = voxel_at(vol, dims, a.x, a.y, a.z), c100 = voxel_at(vol, dims, b.x, a.y, a.z);
  float c010 = voxel_at(vol, dims, a.x, b.y, a.z), c110 = voxel_at(vol, dims, b.x, b.y, a.z);
  float c001 = voxel_at(vol, dims, a.x, a.y, b.z), c101 = voxel_at(vol, dims, b.x, a.y, b.z);
  float c011 = voxel_at(vol, dims, a.x, b.y, b.z), c111 = voxel_at(vol, dims, b.x, b.y, b.z);
  float c00 = mix(c000, c100, f.x), c10 = mix(c010, c110, f.x);
  float c01 = mix(c001, c101, f.x), c11 = mix(c011, c111, f.x);
  float c0 = mix(c00, c10, f.y), c1 = mix(c01, c11, f.y);
  return mix(c0, c1, f.z);
}

#include "reconstruction/slabs.cl"

inline float sample_volume(VOLUME_ARG, __constant RaycastParams* P, float3 p) {
  RETURN_FROM_SLAB(sample_slab, P, p);
}

#endif
