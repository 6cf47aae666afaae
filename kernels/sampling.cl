// Reconstruction of the volume at a point in voxel coordinates (voxel centres at
// integers), clamped to the edge. Options:
//   STORAGE_IMAGE 1: image3d_t (CL_SNORM_INT16), hardware filtering (GPUs)
//   STORAGE_IMAGE 0: a buffer of shorts with manual interpolation (CPUs: PoCL samples a
//                    buffer about 3x faster than an image)
//   INTERP 0 nearest, 1 trilinear
//   SLABS k: the volume in k slabs along z (slabs.cl)
// Every function takes the frame parameters as P: the uber kernel reads INTERP there.
// sample_slab reads one slab (the whole volume when SLABS is 1) of extent dims.
#ifndef VOXRAY_SAMPLING_CL
#define VOXRAY_SAMPLING_CL

#include "variant.cl"

#if STORAGE_IMAGE
#define SLAB_TYPE __read_only image3d_t
__constant sampler_t vol_linear =
    CLK_NORMALIZED_COORDS_FALSE | CLK_ADDRESS_CLAMP_TO_EDGE | CLK_FILTER_LINEAR;
__constant sampler_t vol_nearest =
    CLK_NORMALIZED_COORDS_FALSE | CLK_ADDRESS_CLAMP_TO_EDGE | CLK_FILTER_NEAREST;

// dims: unused, the image clamps at its own edges.
inline float sample_slab(SLAB_TYPE vol, int4 dims, __constant RaycastParams* P, float3 p) {
  // Texel centres sit at +0.5 in unnormalised image coordinates.
  float4 c = (float4)(p + 0.5f, 0.0f);
  float v = INTERP ? read_imagef(vol, vol_linear, c).x : read_imagef(vol, vol_nearest, c).x;
  return v * 32767.0f;
}

#else
#define SLAB_TYPE __global const short* restrict

inline float sample_slab(SLAB_TYPE vol, int4 dims, __constant RaycastParams* P, float3 p) {
  int3 hi = dims.xyz - 1;
  size_t sy = (size_t)dims.x, sz = (size_t)dims.x * dims.y;
  if (!INTERP) {
    int3 i = clamp(convert_int3(floor(p + 0.5f)), (int3)(0), hi);
    return (float)vol[i.z * sz + i.y * sy + i.x];
  }
  float3 f0 = floor(p);
  float3 f = p - f0;
  int3 i0 = convert_int3(f0);
  int3 a = clamp(i0, (int3)(0), hi);
  int3 b = clamp(i0 + 1, (int3)(0), hi);
  size_t za = a.z * sz, zb = b.z * sz, ya = a.y * sy, yb = b.y * sy;
  float c000 = vol[za + ya + a.x], c100 = vol[za + ya + b.x];
  float c010 = vol[za + yb + a.x], c110 = vol[za + yb + b.x];
  float c001 = vol[zb + ya + a.x], c101 = vol[zb + ya + b.x];
  float c011 = vol[zb + yb + a.x], c111 = vol[zb + yb + b.x];
  float c00 = mix(c000, c100, f.x), c10 = mix(c010, c110, f.x);
  float c01 = mix(c001, c101, f.x), c11 = mix(c011, c111, f.x);
  float c0 = mix(c00, c10, f.y), c1 = mix(c01, c11, f.y);
  return mix(c0, c1, f.z);
}
#endif

#include "slabs.cl"

inline float sample_volume(VOLUME_ARG, __constant RaycastParams* P, float3 p) {
  RETURN_FROM_SLAB(sample_slab, P, p);
}

#endif
