// volume_gradient (gradients.cl) for a packet's points at once (march_lanes.cl): the same
// operators, stencils, evaluation order and cancellation rule, lane by lane. The voxel loads are
// gathers; the interpolation and the weighted sums run in floatN lanes, which is what
// makes shading every visible dvr sample affordable on a CPU.
#ifndef VOXRAY_GRADIENTS_LANES_CL
#define VOXRAY_GRADIENTS_LANES_CL

#include "reconstruction/gradients.cl"
#include "reconstruction/sampling_lanes.cl"
#include "shading/shading_lanes.cl"

// Each lane's clamped 4x4x4 voxel block around p, as neighbourhood_trilinear sets it up:
// the x index, row offset and slice offset of each tap, and p's fractional offset.
typedef struct {
  intN x[4], y[4], z[4];
  floatN fx, fy, fz;
} BlockN;

inline BlockN blockN(__constant RaycastParams* P, VecN p) {
  int4 dims = P->dims;
  BlockN b;
  floatN x0 = floor(p.x), y0 = floor(p.y), z0 = floor(p.z);
  b.fx = p.x - x0, b.fy = p.y - y0, b.fz = p.z - z0;
  intN ix = convert_intN(x0) - 1, iy = convert_intN(y0) - 1, iz = convert_intN(z0) - 1;
  for (int k = 0; k < 4; ++k) {
    b.x[k] = clamp(ix + k, 0, dims.x - 1);
    b.y[k] = clamp(iy + k, 0, dims.y - 1) * dims.x;
    b.z[k] = clamp(iz + k, 0, dims.z - 1) * (dims.x * dims.y);
  }
  return b;
}

// Where no lane's block is clamped along x, its x taps are neighbours in memory and come
// in pairs of voxels, each pair one 32-bit load: half the loads of single gathers.
inline bool x_insideN(BlockN b) { return !any((b.x[0] != b.x[1] - 1) | (b.x[3] != b.x[1] + 2)); }

// Taps 1 and 2 of the lanes' rows at `row` (slice + row offsets) into v1, v2, or all four
// taps. Macros: as functions taking the block, PoCL kept them out of line with the block
// in memory, and the gradient ran about 8 % slower.
#define BLOCK8_PAIR(b, inside, row, v1, v2)      \
  if (inside) {                                  \
    pairsN(vol, (row) + (b).x[1], &(v1), &(v2)); \
  } else {                                       \
    v1 = gatherN(vol, (row) + (b).x[1]);         \
    v2 = gatherN(vol, (row) + (b).x[2]);         \
  }
#define BLOCK8_ROW4(b, inside, row, v0, v1, v2, v3) \
  if (inside) {                                     \
    pairsN(vol, (row) + (b).x[0], &(v0), &(v1));    \
    pairsN(vol, (row) + (b).x[2], &(v2), &(v3));    \
  } else {                                          \
    v0 = gatherN(vol, (row) + (b).x[0]);            \
    v1 = gatherN(vol, (row) + (b).x[1]);            \
    v2 = gatherN(vol, (row) + (b).x[2]);            \
    v3 = gatherN(vol, (row) + (b).x[3]);            \
  }

inline floatN abs_maxN(floatN a, floatN b, floatN c, floatN d) {
  return fmax(fmax(fabs(a), fabs(b)), fmax(fabs(c), fabs(d)));
}

// cross_trilinear for each lane's point: s = xm, xp, ym, yp, zm, zp.
inline void cross_trilinearN(__global const short* restrict vol, __constant RaycastParams* P,
                             VecN p, floatN s[6], floatN* largest) {
  BlockN b = blockN(P, p);
  bool inside = x_insideN(b);
  floatN m = 0.0f;
  floatN c[2][2][3];
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y) {
      floatN v0, v1, v2, v3;
      BLOCK8_ROW4(b, inside, b.z[z + 1] + b.y[y + 1], v0, v1, v2, v3);
      m = fmax(m, abs_maxN(v0, v1, v2, v3));
      c[z][y][0] = mix(v0, v1, b.fx);
      c[z][y][1] = mix(v1, v2, b.fx);
      c[z][y][2] = mix(v2, v3, b.fx);
    }
  floatN ey[2][2], ez[2][2];
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 2; ++k) {
      floatN y0, y1, z0, z1;
      BLOCK8_PAIR(b, inside, b.z[a + 1] + b.y[3 * k], y0, y1);
      BLOCK8_PAIR(b, inside, b.z[3 * a] + b.y[k + 1], z0, z1);
      m = fmax(m, abs_maxN(y0, y1, z0, z1));
      ey[a][k] = mix(y0, y1, b.fx);
      ez[a][k] = mix(z0, z1, b.fx);
    }
  floatN fy = b.fy, fz = b.fz;
  s[0] = mix(mix(c[0][0][0], c[0][1][0], fy), mix(c[1][0][0], c[1][1][0], fy), fz);
  s[1] = mix(mix(c[0][0][2], c[0][1][2], fy), mix(c[1][0][2], c[1][1][2], fy), fz);
  s[2] = mix(mix(ey[0][0], c[0][0][1], fy), mix(ey[1][0], c[1][0][1], fy), fz);
  s[3] = mix(mix(c[0][1][1], ey[0][1], fy), mix(c[1][1][1], ey[1][1], fy), fz);
  s[4] = mix(mix(ez[0][0], ez[0][1], fy), mix(c[0][0][1], c[0][1][1], fy), fz);
  s[5] = mix(mix(c[1][0][1], c[1][1][1], fy), mix(ez[1][0], ez[1][1], fy), fz);
  *largest = m;
}

// neighbourhood_trilinear for each lane's point: s[(dz + 1) * 9 + (dy + 1) * 3 + dx + 1].
inline void neighbourhood_trilinearN(__global const short* restrict vol,
                                     __constant RaycastParams* P, VecN p, floatN s[27],
                                     floatN* largest) {
  BlockN b = blockN(P, p);
  bool inside = x_insideN(b);
  floatN x[4][4][3], xy[4][3][3];
  floatN m = 0.0f;
  // Unrolled, and each y interpolation taken once for the two z planes that use it: as
  // loops (PoCL kept them) the taps went through memory. The same operations per value.
#pragma unroll
  for (int z = 0; z < 4; ++z)
#pragma unroll
    for (int y = 0; y < 4; ++y) {
      floatN v0, v1, v2, v3;
      BLOCK8_ROW4(b, inside, b.z[z] + b.y[y], v0, v1, v2, v3);
      m = fmax(m, abs_maxN(v0, v1, v2, v3));
      x[z][y][0] = mix(v0, v1, b.fx);
      x[z][y][1] = mix(v1, v2, b.fx);
      x[z][y][2] = mix(v2, v3, b.fx);
    }
#pragma unroll
  for (int z = 0; z < 4; ++z)
#pragma unroll
    for (int dy = 0; dy < 3; ++dy)
#pragma unroll
      for (int dx = 0; dx < 3; ++dx) xy[z][dy][dx] = mix(x[z][dy][dx], x[z][dy + 1][dx], b.fy);
#pragma unroll
  for (int dz = 0; dz < 3; ++dz)
#pragma unroll
    for (int dy = 0; dy < 3; ++dy)
#pragma unroll
      for (int dx = 0; dx < 3; ++dx)
        s[dz * 9 + dy * 3 + dx] = mix(xy[dz][dy][dx], xy[dz + 1][dy][dx], b.fz);
  *largest = m;
}

#undef BLOCK8_PAIR
#undef BLOCK8_ROW4

// volume_gradient for each lane's point in voxel coordinates, in stored units per voxel.
inline VecN volume_gradientN(__global const short* restrict vol, __constant RaycastParams* P,
                             VecN p) {
  floatN largest = 0.0f;
  VecN g;
  if (GRADIENT == 0) {
    floatN s[6];
    if (INTERP)
      cross_trilinearN(vol, P, p, s, &largest);
    else
      for (int k = 0; k < 6; ++k) {
        float e = k % 2 ? 1.0f : -1.0f;
        s[k] = sampleN(vol, P, k / 2 == 0 ? p.x + e : p.x, k / 2 == 1 ? p.y + e : p.y,
                       k / 2 == 2 ? p.z + e : p.z);
        largest = fmax(largest, fabs(s[k]));
      }
    g.x = 0.5f * (s[1] - s[0]), g.y = 0.5f * (s[3] - s[2]), g.z = 0.5f * (s[5] - s[4]);
  } else {
    float w_face = 1.0f, w_edge = 0.70710678f, w_corner = 0.57735027f;
    float w_sum = 6.13836371f;  // as in volume_gradient
    if (GRADIENT == 1) {
      w_face = 6.0f;
      w_edge = 3.0f;
      w_corner = 1.0f;
      w_sum = 22.0f;
    }
    floatN s[27];
    if (INTERP)
      neighbourhood_trilinearN(vol, P, p, s, &largest);
    else
      for (int k = 0; k < 27; ++k) {
        s[k] = k == 13 ? 0.0f
                       : sampleN(vol, P, p.x + (float)(k % 3 - 1), p.y + (float)(k / 3 % 3 - 1),
                                 p.z + (float)(k / 9 - 1));
        largest = fmax(largest, fabs(s[k]));
      }
    g.x = g.y = g.z = 0.0f;
    // Unrolled, the weights are constants; as a loop (PoCL kept it one) each term
    // recomputed its offsets and weights in scalar code: about a fifth of the flush's time.
#pragma unroll
    for (int k = 0; k < 27; ++k) {
      int dx = k % 3 - 1, dy = k / 3 % 3 - 1, dz = k / 9 - 1;
      int cx = abs(dy) + abs(dz), cy = abs(dx) + abs(dz), cz = abs(dx) + abs(dy);
      float wx = cx == 0 ? w_face : (cx == 1 ? w_edge : w_corner);
      float wy = cy == 0 ? w_face : (cy == 1 ? w_edge : w_corner);
      float wz = cz == 0 ? w_face : (cz == 1 ? w_edge : w_corner);
      if (dx != 0) g.x += s[k] * (dx * wx);
      if (dy != 0) g.y += s[k] * (dy * wy);
      if (dz != 0) g.z += s[k] * (dz * wz);
    }
    float scale = 0.5f / w_sum;
    g.x *= scale, g.y *= scale, g.z *= scale;
  }
  // zero_if_cancelled, lane by lane.
  floatN m = fmax(fabs(g.x), fmax(fabs(g.y), fabs(g.z)));
  intN cancelled = m <= GRADIENT_ZERO_REL * largest;
  g.x = select(g.x, (floatN)(0.0f), cancelled);
  g.y = select(g.y, (floatN)(0.0f), cancelled);
  g.z = select(g.z, (floatN)(0.0f), cancelled);
  return g;
}

// mat_mul (math.cl) of the voxel-gradient -> world-gradient matrix with each lane's vector.
inline VecN gradient_to_worldN(__constant RaycastParams* P, VecN g) {
  float4 a = P->grad_x, b = P->grad_y, c = P->grad_z;
  VecN w = {a.x * g.x + a.y * g.y + a.z * g.z, b.x * g.x + b.y * g.y + b.z * g.z,
            c.x * g.x + c.y * g.y + c.z * g.z};
  return w;
}

#endif
