// shade (shading.cl) for a packet's lanes at once (march_lanes.cl): the same formulas.
#ifndef VOXRAY_SHADING_LANES_CL
#define VOXRAY_SHADING_LANES_CL

#include "shading/shading.cl"
#include "simd/lanes.cl"
#include "simd/math_lanes.cl"

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

// shade for every lane at once: the same formulas; the ambient term scaled by ambient_scale,
// diffuse and specular by light_scale, per lane (frame_light's factors; 1 for phong).
inline VecN shade_scaledN(VecN color, VecN normal_w, VecN pos_w, VecN view_w, float4 light_w,
                          float4 k, floatN ambient_scale, floatN light_scale) {
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
  floatN f = k.x * ambient_scale + k.y * diffuse * light_scale, s = k.z * specular * light_scale;
  VecN out = {color.x * f + s, color.y * f + s, color.z * f + s};
  return out;
}

inline VecN shadeN(VecN color, VecN normal_w, VecN pos_w, VecN view_w, float4 light_w, float4 k) {
  return shade_scaledN(color, normal_w, pos_w, view_w, light_w, k, (floatN)(1.0f), (floatN)(1.0f));
}

// Where shadows (LIGHTING 1) read the light grid for each lane: light_grid's point, the
// sample moved the shadow offset toward the light (toward_light's formulas, lane by lane, so
// only the grid's reads stay scalar: per lane they made shadows frames 1.7x phong's).
// *read is false where light_grid returns 1 without reading: the light within the offset,
// or the point past the clip box.
inline VecN shadow_pointN(__constant RaycastParams* P, VecN at, intN* read) {
  VecN du = {P->light_v.x - at.x, P->light_v.y - at.y, P->light_v.z - at.z};
  floatN m = fmax(fabs(du.x), fmax(fabs(du.y), fabs(du.z)));
  intN ok = (m > 1e-6f) & ~isinf(m);
  m = select((floatN)(1.0f), m, ok);
  VecN u = {du.x / m, du.y / m, du.z / m};
  floatN wx = P->to_world_x.x * u.x + P->to_world_x.y * u.y + P->to_world_x.z * u.z;
  floatN wy = P->to_world_y.x * u.x + P->to_world_y.y * u.y + P->to_world_y.z * u.z;
  floatN wz = P->to_world_z.x * u.x + P->to_world_z.y * u.y + P->to_world_z.z * u.z;
  floatN len = m * sqrt(wx * wx + wy * wy + wz * wz), offset = P->light_march.w;
  ok &= len > offset;
  floatN to = offset / select((floatN)(1.0f), len, ok);
  VecN p = {at.x + du.x * to, at.y + du.y * to, at.z + du.z * to};
  ok &= (p.x >= P->clip_lo.x) & (p.y >= P->clip_lo.y) & (p.z >= P->clip_lo.z);
  ok &= (p.x <= P->clip_hi.x) & (p.y <= P->clip_hi.y) & (p.z <= P->clip_hi.z);
  *read = ok;
  return p;
}

// shadeN with the frame's lighting model at voxel positions at (frame_light, lane by lane).
inline VecN shade_frameN(__global const float4* lut, __constant RaycastParams* P, VecN at,
                         VecN color, VecN normal_w, VecN pos_w, VecN view_w) {
  if (LIGHTING == 0) return shadeN(color, normal_w, pos_w, view_w, P->light_w, P->light);
  intN read = -1;
  if (LIGHTING == 1) at = shadow_pointN(P, at, &read);
  float x[LANES], y[LANES], z[LANES], f[LANES];
  int r[LANES];
  vstoreN(at.x, 0, x), vstoreN(at.y, 0, y), vstoreN(at.z, 0, z), vstoreN(read, 0, r);
  for (int l = 0; l < LANES; ++l)
    f[l] = r[l] ? light_grid_at(lut, P, (float3)(x[l], y[l], z[l])) : 1.0f;
  floatN g = vloadN(0, f), one = 1.0f;
  return shade_scaledN(color, normal_w, pos_w, view_w, P->light_w, P->light,
                       LIGHTING == 2 ? g : one, LIGHTING == 1 ? g : one);
}

#endif
