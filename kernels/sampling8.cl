// Volume reconstruction for eight points at once (packet.cl): sample_volume (sampling.cl)
// with float8 lanes. Only buffers (STORAGE_IMAGE 0) of fewer than 2^31 voxels come here,
// so voxel indices fit an int.
#ifndef VOXRAY_SAMPLING8_CL
#define VOXRAY_SAMPLING8_CL

#include "variant.cl"

inline float8 gather8(__global const short* restrict v, int8 i) {
  return convert_float8(
      (short8)(v[i.s0], v[i.s1], v[i.s2], v[i.s3], v[i.s4], v[i.s5], v[i.s6], v[i.s7]));
}

// Voxels i and i + 1 of each lane, in *a and *b: one 32-bit load per lane.
inline void pairs8(__global const short* restrict v, int8 i, float8* a, float8* b) {
  short2 p0 = vload2(0, v + i.s0), p1 = vload2(0, v + i.s1), p2 = vload2(0, v + i.s2);
  short2 p3 = vload2(0, v + i.s3), p4 = vload2(0, v + i.s4), p5 = vload2(0, v + i.s5);
  short2 p6 = vload2(0, v + i.s6), p7 = vload2(0, v + i.s7);
  *a = convert_float8((short8)(p0.x, p1.x, p2.x, p3.x, p4.x, p5.x, p6.x, p7.x));
  *b = convert_float8((short8)(p0.y, p1.y, p2.y, p3.y, p4.y, p5.y, p6.y, p7.y));
}

// Voxels i and i + 1 of each lane, interpolated by f. Widens [*lo, *hi] to hold both.
inline float8 mix_pairs8(__global const short* restrict v, int8 i, float8 f, float8* lo,
                         float8* hi) {
  float8 a, b;
  pairs8(v, i, &a, &b);
  *lo = fmin(*lo, fmin(a, b));
  *hi = fmax(*hi, fmax(a, b));
  return mix(a, b, f);
}

// sample_volume (sampling.cl) for eight points. Trilinear also returns in [*lo, *hi] a
// range that holds the eight voxels around each point, and so every value trilinear
// interpolation takes in that voxel cell (nearest: the sample itself).
inline float8 sample8_range(__global const short* restrict vol, __constant RaycastParams* P,
                            float8 x, float8 y, float8 z, float8* lo, float8* hi) {
  int4 dims = P->dims;
  int sy = dims.x, sz = dims.x * dims.y;
  if (!INTERP) {
    int8 nx = clamp(convert_int8(floor(x + 0.5f)), 0, dims.x - 1);
    int8 ny = clamp(convert_int8(floor(y + 0.5f)), 0, dims.y - 1);
    int8 nz = clamp(convert_int8(floor(z + 0.5f)), 0, dims.z - 1);
    *lo = *hi = gather8(vol, nz * sz + ny * sy + nx);
    return *lo;
  }
  float8 x0 = floor(x), y0 = floor(y), z0 = floor(z);
  float8 fx = x - x0, fy = y - y0, fz = z - z0;
  int8 ix = convert_int8(x0), iy = convert_int8(y0), iz = convert_int8(z0);
  int8 ya = clamp(iy, 0, dims.y - 1) * sy, yb = clamp(iy + 1, 0, dims.y - 1) * sy;
  int8 za = clamp(iz, 0, dims.z - 1) * sz, zb = clamp(iz + 1, 0, dims.z - 1) * sz;
  float8 c00, c10, c01, c11;
  *lo = FLT_MAX, *hi = -FLT_MAX;
  if (dims.x >= 2) {
    // Each x pair in one load: the pair starts at most at dims.x - 2; past either edge,
    // fx = 0 or 1 picks the edge voxel exactly (clamp to edge, as below).
    int8 ax = clamp(ix, 0, dims.x - 2);
    fx = select(fx, (float8)(0.0f), ix < 0);
    fx = select(fx, (float8)(1.0f), ix > dims.x - 2);
    c00 = mix_pairs8(vol, za + ya + ax, fx, lo, hi);
    c10 = mix_pairs8(vol, za + yb + ax, fx, lo, hi);
    c01 = mix_pairs8(vol, zb + ya + ax, fx, lo, hi);
    c11 = mix_pairs8(vol, zb + yb + ax, fx, lo, hi);
  } else {
    int8 ax = 0;
    c00 = gather8(vol, za + ya + ax), c10 = gather8(vol, za + yb + ax);
    c01 = gather8(vol, zb + ya + ax), c11 = gather8(vol, zb + yb + ax);
    *lo = fmin(fmin(c00, c10), fmin(c01, c11));
    *hi = fmax(fmax(c00, c10), fmax(c01, c11));
  }
  return mix(mix(c00, c10, fy), mix(c01, c11, fy), fz);
}

inline float8 sample8(__global const short* restrict vol, __constant RaycastParams* P, float8 x,
                      float8 y, float8 z) {
  float8 lo, hi;
  return sample8_range(vol, P, x, y, z, &lo, &hi);
}

#endif
