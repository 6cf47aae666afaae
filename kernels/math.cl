// Small numerical helpers that keep every pixel finite.
#ifndef VOXRAY_MATH_CL
#define VOXRAY_MATH_CL

// Normalises v, or returns fallback when v is zero, denormal-small or not finite. Scaling
// by the largest component first keeps a light at 1e30 mm from overflowing the length.
inline float3 safe_normalize(float3 v, float3 fallback) {
  float m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
  if (!(m > 1e-6f) || isinf(m)) return fallback;
  v /= m;
  return v * rsqrt(dot(v, v));
}

inline float3 mat_mul(float4 r0, float4 r1, float4 r2, float3 v) {
  return (float3)(dot(r0.xyz, v), dot(r1.xyz, v), dot(r2.xyz, v));
}

#endif
