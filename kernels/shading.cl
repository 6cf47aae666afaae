// Blinn-Phong with one point light (the seed's Shade(), plus specular), in world space.
#ifndef VOXRAY_SHADING_CL
#define VOXRAY_SHADING_CL

#include "math.cl"

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
    // powr on the fast native path; at 0 it keeps pow's value (0, or 1 for exponent 0).
    float s = fmax(dot(n, h), 0.0f);
    specular = s > 0.0f ? native_exp2(k.w * native_log2(s)) : (k.w == 0.0f ? 1.0f : 0.0f);
  }
  return color * (k.x + k.y * diffuse) + (float3)(k.z * specular);
}

#endif
