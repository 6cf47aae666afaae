// Blinn-Phong with one point light (the seed's Shade(), plus specular), in world space.
#ifndef VOXRAY_SHADING_CL
#define VOXRAY_SHADING_CL

#include "math.cl"

// s^w for s >= 0 on the fast native path, keeping pow's value at s = 0 (0, or 1 for w = 0).
// A macro so that float and the float8 lanes of shade8 share it; vector lanes evaluate
// both branches, so the logarithm never sees 0.
#define SPECULAR_POWER(s, w) \
  ((s) > 0.0f ? native_exp2((w)*native_log2(fmax((s), FLT_MIN))) : ((w) == 0.0f ? 1.0f : 0.0f))

// normal_w need not be unit length or point at the viewer; view_w points to the eye.
// A zero normal (flat region) is treated as facing the viewer, never as NaN.
inline float3 shade(float3 color, float3 normal_w, float3 pos_w, float3 view_w, float4 light_w,
                    float4 k) {
  float3 n = safe_normalize(normal_w, view_w);
  if (dot(n, view_w) < 0.0f) n = -n;  // two-sided: surfaces are seen from either side
  float3 l = safe_normalize(light_w.xyz - pos_w, view_w);
  float diffuse = fmax(dot(n, l), 0.0f);
  float specular = 0.0f;
  if (diffuse > 0.0f) {
    float3 h = safe_normalize(l + view_w, n);
    specular = SPECULAR_POWER(fmax(dot(n, h), 0.0f), k.w);
  }
  return color * (k.x + k.y * diffuse) + (float3)(k.z * specular);
}

// Eight lanes of vectors, as x, y, z components (packet.cl).
typedef struct {
  float8 x, y, z;
} Vec8;

inline float8 dot8(Vec8 a, Vec8 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// safe_normalize (math.cl) lane by lane. Scaling by the largest component only matters
// when the dot product could overflow, so it is skipped (a division saved) unless a lane
// is that large.
inline Vec8 safe_normalize8(Vec8 v, Vec8 fallback) {
  float8 m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
  int8 bad = ~(m > 1e-6f) | isinf(m);
  if (any(m > 1e18f)) {
    float8 inv = 1.0f / select(m, (float8)(1.0f), bad);
    v.x *= inv, v.y *= inv, v.z *= inv;
  }
  float8 r = rsqrt(select(dot8(v, v), (float8)(1.0f), bad));
  Vec8 n = {select(v.x * r, fallback.x, bad), select(v.y * r, fallback.y, bad),
            select(v.z * r, fallback.z, bad)};
  return n;
}

// shade for eight lanes at once: the same formulas.
inline Vec8 shade8(Vec8 color, Vec8 normal_w, Vec8 pos_w, Vec8 view_w, float4 light_w, float4 k) {
  Vec8 n = safe_normalize8(normal_w, view_w);
  float8 flip = select((float8)(1.0f), (float8)(-1.0f), dot8(n, view_w) < 0.0f);
  n.x *= flip, n.y *= flip, n.z *= flip;
  Vec8 to_light = {light_w.x - pos_w.x, light_w.y - pos_w.y, light_w.z - pos_w.z};
  Vec8 l = safe_normalize8(to_light, view_w);
  float8 diffuse = fmax(dot8(n, l), 0.0f);
  Vec8 half_way = {l.x + view_w.x, l.y + view_w.y, l.z + view_w.z};
  Vec8 h = safe_normalize8(half_way, n);
  float8 specular = SPECULAR_POWER(fmax(dot8(n, h), 0.0f), k.w);
  specular = select((float8)(0.0f), specular, diffuse > 0.0f);
  float8 f = k.x + k.y * diffuse, s = k.z * specular;
  Vec8 out = {color.x * f + s, color.y * f + s, color.z * f + s};
  return out;
}

#endif
