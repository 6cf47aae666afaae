// Blinn-Phong with one point light (the seed's Shade(), plus specular), in world space.
#ifndef VOXRAY_SHADING_CL
#define VOXRAY_SHADING_CL

#include "gradient_table.h"
#include "math.cl"
#include "params.cl"
#include "preint_table.h"
#include "tf2d_table.h"

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

// A grid of n.xyz floats (x fastest), trilinear at grid position q, clamped to the grid.
inline float grid_trilinear(__global const float* g, int4 n, float3 q) {
  q = clamp(q, (float3)(0.0f), convert_float3(n.xyz - 1));
  float3 f = floor(q);
  int3 i = convert_int3(f), j = min(i + 1, n.xyz - 1);
  float3 w = q - f;
  int sy = n.x, sz = n.x * n.y;
#define LG(x, y, z) g[(z)*sz + (y)*sy + (x)]
  float c00 = mix(LG(i.x, i.y, i.z), LG(j.x, i.y, i.z), w.x);
  float c10 = mix(LG(i.x, j.y, i.z), LG(j.x, j.y, i.z), w.x);
  float c01 = mix(LG(i.x, i.y, j.z), LG(j.x, i.y, j.z), w.x);
  float c11 = mix(LG(i.x, j.y, j.z), LG(j.x, j.y, j.z), w.x);
#undef LG
  return mix(mix(c00, c10, w.y), mix(c01, c11, w.y), w.z);
}

// Length in mm of a step du in voxel coordinates.
inline float voxel_mm(__constant RaycastParams* P, float3 du) {
  float3 w =
      (float3)(dot(P->to_world_x.xyz, du), dot(P->to_world_y.xyz, du), dot(P->to_world_z.xyz, du));
  return length(w);
}

// The light seen from voxel position p: its distance in mm (0 where it sits at p or is not
// finite), *dv voxels per mm toward it. Scaled first: a light far away ("at infinity") must
// not overflow the length.
inline float toward_light(__constant RaycastParams* P, float3 p, float3* dv) {
  float3 du = P->light_v.xyz - p;
  float m = fmax(fabs(du.x), fmax(fabs(du.y), fabs(du.z)));
  if (!(m > 1e-6f) || !isfinite(m)) return 0.0f;
  float len = voxel_mm(P, du / m);
  *dv = du / (m * len);
  return m * len;
}

// LIGHTING 1 or 2: the light grid (light_volume.cl) behind the table's P->dims.w entries, at
// voxel position p_v (grid point g sits at voxel g * cell). shadows reads the transmittance
// the shadow offset toward the light (the model's T, monte_carlo_reference.h): there, unlike
// at p_v, the grid's interpolation does not reach points inside the sample's own surface,
// which darkened lit surfaces (the grid held T from each point's own offset before).
// The grid's value at voxel position p_v, read where it is stored: behind the table (and
// behind the gradient-opacity table, GRADIENT_OPACITY).
inline float light_grid_at(__global const float4* lut, __constant RaycastParams* P, float3 p_v) {
  __global const float4* grid = lut + P->dims.w;
#if GRADIENT_OPACITY
  grid += VOXRAY_GRADIENT_TABLE_FLOAT4S;
#endif
#if TF2D
  grid += VOXRAY_TF2D_FLOAT4S;
#endif
#if PREINT
  grid += VOXRAY_PREINT_FLOAT4S;
#endif
  return grid_trilinear((__global const float*)grid, P->light_grid, p_v * P->light_march.z);
}

inline float light_grid(__global const float4* lut, __constant RaycastParams* P, float3 p_v) {
  if (LIGHTING == 1) {
    float3 dv = (float3)(0.0f);
    float len = toward_light(P, p_v, &dv), offset = P->light_march.w;
    if (!(len > offset)) return 1.0f;  // the light within the offset: nothing between
    p_v += dv * offset;
    // Past the clip box toward the light nothing occludes (the grid would clamp to its edge).
    if (any(p_v < P->clip_lo.xyz) || any(p_v > P->clip_hi.xyz)) return 1.0f;
  }
  return light_grid_at(lut, P, p_v);
}

// The light coefficients (ambient, diffuse, specular, shininess) of a sample at p_v: the
// frame's for phong; shadows scale diffuse and specular by the transmittance toward the
// light, ao the ambient by the ambient visibility. Phong compiles to P->light alone.
inline float4 frame_light(__global const float4* lut, __constant RaycastParams* P, float3 p_v) {
  float4 k = P->light;
  if (LIGHTING == 0) return k;
  float f = light_grid(lut, P, p_v);
  return LIGHTING == 1 ? (float4)(k.x, k.y * f, k.z * f, k.w) : (float4)(k.x * f, k.yzw);
}

inline uchar4 to_rgba8(float3 color) {
  return (uchar4)(convert_uchar3_sat_rte(clamp(color, 0.0f, 1.0f) * 255.0f), 255);
}

#endif
