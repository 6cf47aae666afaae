// Blinn-Phong with one point light (the seed's Shade(), plus specular), in world space.
#ifndef VOXRAY_SHADING_CL
#define VOXRAY_SHADING_CL

#include "math.cl"

// s^w for s >= 0 by EXP2(w LOG2(s)), keeping pow's value at s = 0 (0, or 1 for w = 0).
// A macro so that float (native_) and the floatN lanes of shadeN (math_lanes.cl) share it;
// vector lanes evaluate both branches, so the logarithm never sees 0.
#define SPECULAR_POWER_BY(s, w, LOG2, EXP2) \
  ((s) > 0.0f ? EXP2((w)*LOG2(fmax((s), FLT_MIN))) : ((w) == 0.0f ? 1.0f : 0.0f))
#define SPECULAR_POWER(s, w) SPECULAR_POWER_BY(s, w, native_log2, native_exp2)

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

inline uchar4 to_rgba8(float3 color) {
  return (uchar4)(convert_uchar3_sat_rte(clamp(color, 0.0f, 1.0f) * 255.0f), 255);
}

#endif
