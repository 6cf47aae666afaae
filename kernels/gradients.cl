// Gradient operators on the reconstructed volume, in stored units per voxel along the
// volume axes (the caller converts to per-mm in patient space). Option GRADIENT:
//   0 central difference (6 samples, the seed's first operator)
//   1 Sobel 3D with the seed's masks (smoothing 1-3-1 / 3-6-3 across the derivative axis)
//   2 Zucker-Hummel (weights 1, 1/sqrt 2, 1/sqrt 3 by distance)
// Each is normalised so that a linear ramp of slope 1 per voxel gives exactly 1.
#ifndef VOXRAY_GRADIENTS_CL
#define VOXRAY_GRADIENTS_CL

#include "sampling.cl"

// Volume samples one gradient takes (for the sample counter).
#define GRADIENT_TAPS (GRADIENT == 0 ? 6 : 26)

#if !STORAGE_IMAGE
// The 27 trilinear samples at p + {-1, 0, 1}^3 share p's fractional offset, so they come
// from one clamped 4x4x4 block of voxels interpolated along x, then y, then z (the order
// sample_volume uses): 64 loads instead of 216, the same values.
inline void neighbourhood_trilinear(VOLUME_ARG, __constant RaycastParams* P, float3 p, float* s) {
  int4 dims = P->dims;
  float3 f0 = floor(p);
  float3 f = p - f0;
  int3 i0 = convert_int3(f0) - 1;
  int3 hi = dims.xyz - 1;
  int xs[4];
  for (int k = 0; k < 4; ++k) xs[k] = clamp(i0.x + k, 0, hi.x);
  float x[4][4][3];  // [z][y][x tap]: interpolated along x
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y) {
      size_t row = ((size_t)clamp(i0.z + z, 0, hi.z) * dims.y + clamp(i0.y + y, 0, hi.y)) * dims.x;
      float v0 = vol[row + xs[0]], v1 = vol[row + xs[1]], v2 = vol[row + xs[2]];
      float v3 = vol[row + xs[3]];
      x[z][y][0] = mix(v0, v1, f.x);
      x[z][y][1] = mix(v1, v2, f.x);
      x[z][y][2] = mix(v2, v3, f.x);
    }
  for (int dz = 0; dz < 3; ++dz)
    for (int dy = 0; dy < 3; ++dy)
      for (int dx = 0; dx < 3; ++dx) {
        float c0 = mix(x[dz][dy][dx], x[dz][dy + 1][dx], f.y);
        float c1 = mix(x[dz + 1][dy][dx], x[dz + 1][dy + 1][dx], f.y);
        s[dz * 9 + dy * 3 + dx] = mix(c0, c1, f.z);
      }
}
#endif

inline float3 volume_gradient(VOLUME_ARG, __constant RaycastParams* P, float3 p) {
  if (GRADIENT == 0) {
    float3 g;
    g.x =
        sample_volume(vol, P, p + (float3)(1, 0, 0)) - sample_volume(vol, P, p - (float3)(1, 0, 0));
    g.y =
        sample_volume(vol, P, p + (float3)(0, 1, 0)) - sample_volume(vol, P, p - (float3)(0, 1, 0));
    g.z =
        sample_volume(vol, P, p + (float3)(0, 0, 1)) - sample_volume(vol, P, p - (float3)(0, 0, 1));
    return 0.5f * g;
  }
  // Weight of a neighbour by how many of its two cross-axis offsets are non-zero.
  float w_face = 1.0f, w_edge = 0.70710678f, w_corner = 0.57735027f;
  float w_sum = 6.13836371f;  // 1 + 4 / sqrt 2 + 4 / sqrt 3
  if (GRADIENT == 1) {
    w_face = 6.0f;
    w_edge = 3.0f;
    w_corner = 1.0f;
    w_sum = 22.0f;
  }
  float s[27];  // the samples at p + (dx, dy, dz), index (dz + 1) * 9 + (dy + 1) * 3 + dx + 1
#if !STORAGE_IMAGE
  if (INTERP)
    neighbourhood_trilinear(vol, P, p, s);
  else
#endif
    for (int k = 0; k < 27; ++k)  // the centre (13) has weight 0
      s[k] =
          k == 13 ? 0.0f : sample_volume(vol, P, p + (float3)(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1));
  float3 g = (float3)(0.0f);
  for (int k = 0; k < 27; ++k) {
    int dx = k % 3 - 1, dy = k / 3 % 3 - 1, dz = k / 9 - 1;
    // Cross-axis weight for component x depends on |dy| + |dz|, etc.
    int cx = abs(dy) + abs(dz), cy = abs(dx) + abs(dz), cz = abs(dx) + abs(dy);
    float wx = cx == 0 ? w_face : (cx == 1 ? w_edge : w_corner);
    float wy = cy == 0 ? w_face : (cy == 1 ? w_edge : w_corner);
    float wz = cz == 0 ? w_face : (cz == 1 ? w_edge : w_corner);
    g += s[k] * (float3)(dx * wx, dy * wy, dz * wz);
  }
  return g * (0.5f / w_sum);
}
#endif
