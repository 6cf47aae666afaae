// Gradient operators on the reconstructed volume, in stored units per voxel along the
// volume axes (the caller converts to per-mm in patient space). Option GRADIENT:
//   0 central difference (6 samples, the seed's first operator)
//   1 Sobel 3D with the seed's masks (smoothing 1-3-1 / 3-6-3 across the derivative axis)
//   2 Zucker-Hummel (weights 1, 1/sqrt 2, 1/sqrt 3 by distance)
// Each is normalised so that a linear ramp of slope 1 per voxel gives exactly 1.
#ifndef VOXRAY_GRADIENTS_CL
#define VOXRAY_GRADIENTS_CL

#include "reconstruction/sampling.cl"

// Volume samples one gradient takes (for the sample counter).
#define GRADIENT_TAPS (GRADIENT == 0 ? 6 : 26)

// A gradient whose largest component is at most this fraction of the largest |voxel| its
// stencil read is float cancellation noise, not a direction: neighbours near +-32767 that
// are equal in exact arithmetic differ by ~|v| 2^-23 in float. Such a gradient is returned
// as 0, so shading falls back as for a flat region. engine/src/reference_sampling.cpp
// applies the same rule in double.
#define GRADIENT_ZERO_REL 1e-5f

inline float3 zero_if_cancelled(float3 g, float largest_voxel) {
  float m = fmax(fabs(g.x), fmax(fabs(g.y), fabs(g.z)));
  return m <= GRADIENT_ZERO_REL * largest_voxel ? (float3)(0.0f) : g;
}

// The 27 trilinear samples at p + {-1, 0, 1}^3 share p's fractional offset, so they come
// from one clamped 4x4x4 block of voxels interpolated along x, then y, then z (the order
// sample_volume uses): 64 loads instead of 216, the same values. *largest: the largest
// |voxel| of the block.
inline void neighbourhood_trilinear(SLAB_TYPE vol, int4 dims, float3 p, float* s, float* largest) {
  float3 f0 = floor(p);
  float3 f = p - f0;
  int3 i0 = convert_int3(f0) - 1;
  int3 hi = dims.xyz - 1;
  int xs[4];
  for (int k = 0; k < 4; ++k) xs[k] = clamp(i0.x + k, 0, hi.x);
  float x[4][4][3];  // [z][y][x tap]: interpolated along x
  float m = 0.0f;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y) {
      int zr = clamp(i0.z + z, 0, hi.z), yr = clamp(i0.y + y, 0, hi.y);
      float v0 = voxel_at(vol, dims, xs[0], yr, zr), v1 = voxel_at(vol, dims, xs[1], yr, zr);
      float v2 = voxel_at(vol, dims, xs[2], yr, zr), v3 = voxel_at(vol, dims, xs[3], yr, zr);
      m = fmax(m, fmax(fmax(fabs(v0), fabs(v1)), fmax(fabs(v2), fabs(v3))));
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
  *largest = m;
}

// The six trilinear samples at p -+ 1 along x, y, z (s: xm, xp, ym, yp, zm, zp), from the
// 32 voxels of the same 4x4x4 block that a cross through its centre cell covers, in
// sample_volume's order: 32 loads instead of 48. *largest: the largest |voxel| read.
inline void cross_trilinear(SLAB_TYPE vol, int4 dims, float3 p, float* s, float* largest) {
  float3 f0 = floor(p);
  float3 f = p - f0;
  int3 i0 = convert_int3(f0) - 1;
  int3 hi = dims.xyz - 1;
  int xs[4], ys[4], zs[4];
  for (int k = 0; k < 4; ++k) {
    xs[k] = clamp(i0.x + k, 0, hi.x);
    ys[k] = clamp(i0.y + k, 0, hi.y);
    zs[k] = clamp(i0.z + k, 0, hi.z);
  }
#define VOXEL(tz, ty, tx) voxel_at(vol, dims, xs[tx], ys[ty], zs[tz])
  float m = 0.0f;
  float c[2][2][3];  // centre rows (y, z taps 1..2) along x at offsets -1, 0, +1
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y) {
      float v0 = VOXEL(z + 1, y + 1, 0), v1 = VOXEL(z + 1, y + 1, 1);
      float v2 = VOXEL(z + 1, y + 1, 2), v3 = VOXEL(z + 1, y + 1, 3);
      m = fmax(m, fmax(fmax(fabs(v0), fabs(v1)), fmax(fabs(v2), fabs(v3))));
      c[z][y][0] = mix(v0, v1, f.x);
      c[z][y][1] = mix(v1, v2, f.x);
      c[z][y][2] = mix(v2, v3, f.x);
    }
  float ey[2][2], ez[2][2];  // outer rows at x offset 0: [z tap 1..2][y tap 0 / 3], [z 0 / 3][y]
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      float y0 = VOXEL(a + 1, 3 * b, 1), y1 = VOXEL(a + 1, 3 * b, 2);
      float z0 = VOXEL(3 * a, b + 1, 1), z1 = VOXEL(3 * a, b + 1, 2);
      m = fmax(m, fmax(fmax(fabs(y0), fabs(y1)), fmax(fabs(z0), fabs(z1))));
      ey[a][b] = mix(y0, y1, f.x);
      ez[a][b] = mix(z0, z1, f.x);
    }
#undef VOXEL
  s[0] = mix(mix(c[0][0][0], c[0][1][0], f.y), mix(c[1][0][0], c[1][1][0], f.y), f.z);
  s[1] = mix(mix(c[0][0][2], c[0][1][2], f.y), mix(c[1][0][2], c[1][1][2], f.y), f.z);
  s[2] = mix(mix(ey[0][0], c[0][0][1], f.y), mix(ey[1][0], c[1][0][1], f.y), f.z);
  s[3] = mix(mix(c[0][1][1], ey[0][1], f.y), mix(c[1][1][1], ey[1][1], f.y), f.z);
  s[4] = mix(mix(ez[0][0], ez[0][1], f.y), mix(c[0][0][1], c[0][1][1], f.y), f.z);
  s[5] = mix(mix(c[1][0][1], c[1][1][1], f.y), mix(ez[1][0], ez[1][1], f.y), f.z);
  *largest = m;
}

// The gradient at p in one slab (the whole volume when SLABS is 1) of extent dims.
inline float3 volume_gradient_slab(SLAB_TYPE vol, int4 dims, __constant RaycastParams* P,
                                   float3 p) {
  float largest = 0.0f;  // the largest |voxel| the stencil read (see GRADIENT_ZERO_REL)
  if (GRADIENT == 0) {
    float s[6];  // p - x, p + x, p - y, p + y, p - z, p + z
    if (INTERP)
      cross_trilinear(vol, dims, p, s, &largest);
    else
      for (int k = 0; k < 6; ++k) {
        float3 e = (float3)(k / 2 == 0, k / 2 == 1, k / 2 == 2);
        s[k] = sample_slab(vol, dims, P, k % 2 ? p + e : p - e);
        // Nearest samples are voxels.
        largest = fmax(largest, fabs(s[k]));
      }
    return zero_if_cancelled(0.5f * (float3)(s[1] - s[0], s[3] - s[2], s[5] - s[4]), largest);
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
  if (INTERP)
    neighbourhood_trilinear(vol, dims, p, s, &largest);
  else
    for (int k = 0; k < 27; ++k) {  // the centre (13) has weight 0
      float3 q = p + (float3)(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
      s[k] = k == 13 ? 0.0f : sample_slab(vol, dims, P, q);
      largest = fmax(largest, fabs(s[k]));
    }
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
  return zero_if_cancelled(g * (0.5f / w_sum), largest);
}

// The block (or every tap) lies in the slab owning floor(p.z): slabs.cl.
inline float3 volume_gradient(VOLUME_ARG, __constant RaycastParams* P, float3 p) {
  RETURN_FROM_SLAB(volume_gradient_slab, P, p);
}
#endif
