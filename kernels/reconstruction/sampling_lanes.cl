// Volume reconstruction for a packet's points at once (march_lanes.cl): sample_volume (sampling.cl)
// with floatN lanes. Only buffers (STORAGE_IMAGE 0) of fewer than 2^31 voxels come here,
// so voxel indices fit an int.
#ifndef VOXRAY_SAMPLING_LANES_CL
#define VOXRAY_SAMPLING_LANES_CL

#include "simd/lanes.cl"
#include "variant.cl"

// On x86 CPUs each load below is one gather instruction with 32-bit indices. From lane-by-
// lane loads LLVM builds gathers with 64-bit indices: two per 16 lanes, after widening the
// indices (5-8 % of a CT frame's kernel time). Voxels are gathered as 32-bit words, a voxel
// with its neighbour.
#if defined(__AVX512F__) && LANES == 16
#define VOXRAY_GATHER32
inline intN gather_wordsN(__global const short* restrict v, intN i) {
  return __builtin_ia32_gathersiv16si((intN)(0), (const void*)(ulong)v, i, (ushort)0xffff, 2);
}
inline floatN gather_floatN(__global const float* restrict p, intN i) {
  return __builtin_ia32_gathersiv16sf((floatN)(0.0f), (const void*)(ulong)p, i, (ushort)0xffff, 4);
}
#elif defined(__AVX2__) && LANES == 8
#define VOXRAY_GATHER32
inline intN gather_wordsN(__global const short* restrict v, intN i) {
  return __builtin_ia32_gatherd_d256((intN)(0), (const void*)(ulong)v, i, (intN)(-1), 2);
}
inline floatN gather_floatN(__global const float* restrict p, intN i) {
  return __builtin_ia32_gatherd_ps256((floatN)(0.0f), (const void*)(ulong)p, i,
                                      as_floatN((intN)(-1)), 4);
}
#endif

#ifdef VOXRAY_GATHER32
// v[i] as the high half of the word at i - 1 (the low half of the word at 0): the words stay
// inside the buffer, whose last voxel may end it.
inline floatN gatherN(__global const short* restrict v, intN i) {
  intN w = gather_wordsN(v, max(i - 1, 0));
  return convert_floatN(select(w >> 16, (w << 16) >> 16, i == 0));
}

// Voxels i and i + 1 of each lane, in *a and *b: one 32-bit word per lane.
inline void pairsN(__global const short* restrict v, intN i, floatN* a, floatN* b) {
  intN w = gather_wordsN(v, i);
  *a = convert_floatN((w << 16) >> 16);
  *b = convert_floatN(w >> 16);
}
#else
inline floatN gatherN(__global const short* restrict v, intN i) {
#define GATHER_LANE(l, n) v[i.s##l]
  return convert_floatN((shortN)(LANE_LIST(GATHER_LANE)));
#undef GATHER_LANE
}

// p[i] for each lane.
inline floatN gather_floatN(__global const float* restrict p, intN i) {
#define GATHER_FLOAT_LANE(l, n) p[i.s##l]
  return (floatN)(LANE_LIST(GATHER_FLOAT_LANE));
#undef GATHER_FLOAT_LANE
}

// Voxels i and i + 1 of each lane, in *a and *b: one 32-bit load per lane.
inline void pairsN(__global const short* restrict v, intN i, floatN* a, floatN* b) {
  short2 p[LANES];
#define PAIR_LOAD(l, n) p[n] = vload2(0, v + i.s##l);
#define PAIR_X(l, n) p[n].x
#define PAIR_Y(l, n) p[n].y
  LANE_EACH(PAIR_LOAD)
  *a = convert_floatN((shortN)(LANE_LIST(PAIR_X)));
  *b = convert_floatN((shortN)(LANE_LIST(PAIR_Y)));
#undef PAIR_LOAD
#undef PAIR_X
#undef PAIR_Y
}
#endif

// Voxels i and i + 1 of each lane, interpolated by f. Widens [*lo, *hi] to hold both.
inline floatN mix_pairsN(__global const short* restrict v, intN i, floatN f, floatN* lo,
                         floatN* hi) {
  floatN a, b;
  pairsN(v, i, &a, &b);
  *lo = fmin(*lo, fmin(a, b));
  *hi = fmax(*hi, fmax(a, b));
  return mix(a, b, f);
}

// sample_volume (sampling.cl) for each lane's point. Trilinear also returns in [*lo, *hi] a
// range that holds the eight voxels around each point, and so every value trilinear
// interpolation takes in that voxel cell (nearest: the sample itself). Always inlined, so
// that sampleN drops the range (PoCL kept it a call that stored both).
inline __attribute__((always_inline)) floatN sample_rangeN(__global const short* restrict vol,
                                                           __constant RaycastParams* P, floatN x,
                                                           floatN y, floatN z, floatN* lo,
                                                           floatN* hi) {
  int4 dims = P->dims;
  int sy = dims.x, sz = dims.x * dims.y;
  if (!INTERP) {
    intN nx = clamp(convert_intN(floor(x + 0.5f)), 0, dims.x - 1);
    intN ny = clamp(convert_intN(floor(y + 0.5f)), 0, dims.y - 1);
    intN nz = clamp(convert_intN(floor(z + 0.5f)), 0, dims.z - 1);
    *lo = *hi = gatherN(vol, nz * sz + ny * sy + nx);
    return *lo;
  }
  floatN x0 = floor(x), y0 = floor(y), z0 = floor(z);
  floatN fx = x - x0, fy = y - y0, fz = z - z0;
  intN ix = convert_intN(x0), iy = convert_intN(y0), iz = convert_intN(z0);
  intN ya = clamp(iy, 0, dims.y - 1) * sy, yb = clamp(iy + 1, 0, dims.y - 1) * sy;
  intN za = clamp(iz, 0, dims.z - 1) * sz, zb = clamp(iz + 1, 0, dims.z - 1) * sz;
  floatN c00, c10, c01, c11;
  *lo = FLT_MAX, *hi = -FLT_MAX;
  if (dims.x >= 2) {
    // Each x pair in one load: the pair starts at most at dims.x - 2; past either edge,
    // fx = 0 or 1 picks the edge voxel exactly (clamp to edge, as below).
    intN ax = clamp(ix, 0, dims.x - 2);
    fx = select(fx, (floatN)(0.0f), ix < 0);
    fx = select(fx, (floatN)(1.0f), ix > dims.x - 2);
    c00 = mix_pairsN(vol, za + ya + ax, fx, lo, hi);
    c10 = mix_pairsN(vol, za + yb + ax, fx, lo, hi);
    c01 = mix_pairsN(vol, zb + ya + ax, fx, lo, hi);
    c11 = mix_pairsN(vol, zb + yb + ax, fx, lo, hi);
  } else {
    intN ax = 0;
    c00 = gatherN(vol, za + ya + ax), c10 = gatherN(vol, za + yb + ax);
    c01 = gatherN(vol, zb + ya + ax), c11 = gatherN(vol, zb + yb + ax);
    *lo = fmin(fmin(c00, c10), fmin(c01, c11));
    *hi = fmax(fmax(c00, c10), fmax(c01, c11));
  }
  return mix(mix(c00, c10, fy), mix(c01, c11, fy), fz);
}

inline floatN sampleN(__global const short* restrict vol, __constant RaycastParams* P, floatN x,
                      floatN y, floatN z) {
  floatN lo, hi;
  return sample_rangeN(vol, P, x, y, z, &lo, &hi);
}

#endif
