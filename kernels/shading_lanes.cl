// shade (shading.cl) for a packet's lanes at once (march_lanes.cl): the same formulas.
#ifndef VOXRAY_SHADING_LANES_CL
#define VOXRAY_SHADING_LANES_CL

#include "lanes.cl"
#include "math_lanes.cl"
#include "shading.cl"

// Vectors in lanes, as x, y, z components.
typedef struct {
  floatN x, y, z;
} VecN;

inline floatN dotN(VecN a, VecN b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// safe_normalize (math.cl) lane by lane. Scaling by the largest component only matters
// when the dot product could overflow, so it is skipped (a division saved) unless a lane
// is that large.
inline VecN safe_normalizeN(VecN v, VecN fallback) {
  floatN m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
  intN bad = ~(m > 1e-6f) | isinf(m);
  if (any(m > 1e18f)) {
    floatN inv = 1.0f / select(m, (floatN)(1.0f), bad);
    v.x *= inv, v.y *= inv, v.z *= inv;
  }
  floatN r = rsqrt(select(dotN(v, v), (floatN)(1.0f), bad));
  VecN n = {select(v.x * r, fallback.x, bad), select(v.y * r, fallback.y, bad),
            select(v.z * r, fallback.z, bad)};
  return n;
}

// shade for every lane at once: the same formulas.
inline VecN shadeN(VecN color, VecN normal_w, VecN pos_w, VecN view_w, float4 light_w, float4 k) {
  VecN n = safe_normalizeN(normal_w, view_w);
  floatN flip = select((floatN)(1.0f), (floatN)(-1.0f), dotN(n, view_w) < 0.0f);
  n.x *= flip, n.y *= flip, n.z *= flip;
  VecN to_light = {light_w.x - pos_w.x, light_w.y - pos_w.y, light_w.z - pos_w.z};
  VecN l = safe_normalizeN(to_light, view_w);
  floatN diffuse = fmax(dotN(n, l), 0.0f);
  // n.h for h = l + v normalised, without normalising h: (n.l + n.v) / |l + v|; where
  // l + v vanishes, h falls back to n as in shade (n.h = 1).
  VecN half_way = {l.x + view_w.x, l.y + view_w.y, l.z + view_w.z};
  floatN hh = dotN(half_way, half_way);
  intN no_half = ~(hh > 1e-12f);
  floatN nh = (dotN(n, l) + dotN(n, view_w)) * rsqrt(select(hh, (floatN)(1.0f), no_half));
  nh = select(nh, (floatN)(1.0f), no_half);
  floatN specular = SPECULAR_POWER_BY(fmax(nh, 0.0f), k.w, fast_log2N, fast_exp2N);
  specular = select((floatN)(0.0f), specular, diffuse > 0.0f);
  floatN f = k.x + k.y * diffuse, s = k.z * specular;
  VecN out = {color.x * f + s, color.y * f + s, color.z * f + s};
  return out;
}

#endif
