// Gradient operators on the reconstructed volume, in stored units per voxel along the
// volume axes (the caller converts to per-mm in patient space). Option GRADIENT:
//   0 central difference (6 samples, the seed's first operator)
//   1 Sobel 3D with the seed's masks (smoothing 1-3-1 / 3-6-3 across the derivative axis)
//   2 Zucker-Hummel (weights 1, 1/sqrt 2, 1/sqrt 3 by distance)
// Each is normalised so that a linear ramp of slope 1 per voxel gives exactly 1.
#ifndef VOXRAY_GRADIENTS_CL
#define VOXRAY_GRADIENTS_CL

#include "sampling.cl"

#if GRADIENT == 0
inline float3 volume_gradient(VOLUME_ARG, int4 dims, float3 p) {
  float3 g;
  g.x = sample_volume(vol, dims, p + (float3)(1, 0, 0)) - sample_volume(vol, dims, p - (float3)(1, 0, 0));
  g.y = sample_volume(vol, dims, p + (float3)(0, 1, 0)) - sample_volume(vol, dims, p - (float3)(0, 1, 0));
  g.z = sample_volume(vol, dims, p + (float3)(0, 0, 1)) - sample_volume(vol, dims, p - (float3)(0, 0, 1));
  return 0.5f * g;
}
#else

#if GRADIENT == 1
// Weight of a neighbour by how many of its two cross-axis offsets are non-zero.
#define W_FACE 6.0f
#define W_EDGE 3.0f
#define W_CORNER 1.0f
#define W_SUM 22.0f
#else
#define W_FACE 1.0f
#define W_EDGE 0.70710678f
#define W_CORNER 0.57735027f
#define W_SUM 6.13836371f  // 1 + 4 / sqrt 2 + 4 / sqrt 3
#endif

inline float3 volume_gradient(VOLUME_ARG, int4 dims, float3 p) {
  // One pass over the 26 neighbours; each contributes to the components it is off-centre in.
  float3 g = (float3)(0.0f);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        int n = abs(dx) + abs(dy) + abs(dz);
        if (n == 0) continue;
        float v = sample_volume(vol, dims, p + (float3)(dx, dy, dz));
        // Cross-axis weight for component x depends on |dy| + |dz|, etc.
        int cx = abs(dy) + abs(dz), cy = abs(dx) + abs(dz), cz = abs(dx) + abs(dy);
        float wx = cx == 0 ? W_FACE : (cx == 1 ? W_EDGE : W_CORNER);
        float wy = cy == 0 ? W_FACE : (cy == 1 ? W_EDGE : W_CORNER);
        float wz = cz == 0 ? W_FACE : (cz == 1 ? W_EDGE : W_CORNER);
        g += v * (float3)(dx * wx, dy * wy, dz * wz);
      }
  return g * (0.5f / W_SUM);
}
#endif

#endif
