// One ray through the clip box and the positions of its samples, shared by every mode
// and by the empty-space skipping that leaps over them. t is in mm along the ray; the
// position in voxel coordinates is o + t * d.
#ifndef VOXRAY_RAY_CL
#define VOXRAY_RAY_CL

#include "adaptive/image_pass.cl"
#include "intersection/intersect.cl"
#include "jitter_hash.h"
#include "variant.cl"

typedef struct {
  float3 o, d;   // origin and direction in voxel coordinates (d per mm)
  float3 inv_d;  // 1 / d, 0 where d is 0 (cell exits never divide by zero)
  float t0, t1;  // clip-box entry and exit
  float step;    // mm between samples
  float j;       // jitter: samples move forward by j steps (0 without JITTER)
  int n;         // ceil((t1 - t0) / step): samples or segments are numbered 0 ... n
} Ray;

// The per-pixel jitter fraction in [0, 1) (jitter_hash.h).
inline float jitter_fraction(int px, int py) {
  return (float)VOXRAY_JITTER_HASH((uint)px, (uint)py) / VOXRAY_JITTER_RANGE;
}

// iso and mip: sample i at t0 + (i + j) * step, the last one clamped to t1.
inline float ray_sample_t(const Ray* r, int i) { return fmin(r->t0 + (i + r->j) * r->step, r->t1); }

// dvr: segment i spans [max(t0, t0 + (i - 1 + j) step), min(t1, t0 + (i + j) step)].
inline float2 ray_segment(const Ray* r, int i) {
  float a = fmax(r->t0, r->t0 + (i - 1 + r->j) * r->step);
  float b = fmin(r->t1, r->t0 + (i + r->j) * r->step);
  return (float2)(a, b);
}

// Where sample (or segment midpoint, when `segments`) i lies along the ray.
inline float ray_t(const Ray* r, int i, bool segments) {
  if (!segments) return ray_sample_t(r, i);
  float2 s = ray_segment(r, i);
  return 0.5f * (s.x + s.y);
}

// The first index whose sample lies at or beyond t, in 0 ... n + 1. Samples are at
// t0 + (i + j) step, midpoints half a step earlier; only the last can be clamped, and
// clamping moves it backwards, so every index below the result lies before t.
inline int ray_index_at(const Ray* r, float t, bool segments) {
  float k = (t - r->t0) / r->step - r->j + (segments ? 0.5f : 0.0f);
  return (int)clamp(ceil(k), 0.0f, (float)(r->n + 1));
}

// Pixel (px, py)'s ray in voxel coordinates (r) and in world space (origin_w, dir_w),
// clipped to the clip box. Returns the clip box's entry axis (0..2), -1 when the eye is
// inside it, or -2 when the ray misses it (r is then incomplete).
inline int pixel_ray(__constant RaycastParams* P, int px, int py, Ray* r, float3* origin_w,
                     float3* dir_w) {
  int width = P->image.x, height = P->image.y;
  float sx = (2.0f * (px + 0.5f) / width - 1.0f) * P->view.x * P->view.y;
  float sy = (1.0f - 2.0f * (py + 0.5f) / height) * P->view.x;
  if (ORTHO) {
    *origin_w = P->eye_w.xyz + P->right_w.xyz * sx + P->up_w.xyz * sy;
    *dir_w = P->forward_w.xyz;
    r->o = P->eye_v.xyz + P->right_v.xyz * sx + P->up_v.xyz * sy;
    r->d = P->forward_v.xyz;
  } else {
    *origin_w = P->eye_w.xyz;
    float3 unnorm = P->forward_w.xyz + P->right_w.xyz * sx + P->up_w.xyz * sy;
    float inv_len = rsqrt(dot(unnorm, unnorm));
    *dir_w = unnorm * inv_len;
    r->o = P->eye_v.xyz;
    r->d = (P->forward_v.xyz + P->right_v.xyz * sx + P->up_v.xyz * sy) * inv_len;
  }
  int axis = intersect_box(r->o, r->d, P->clip_lo.xyz, P->clip_hi.xyz, &r->t0, &r->t1);
  if (axis > -2) {
    r->step = P->view.z;
    r->inv_d = select(1.0f / r->d, (float3)(0.0f), isequal(r->d, 0.0f));
    r->j = JITTER ? jitter_fraction(px, py) : 0.0f;
    // A bounded count: a NaN or absurd length must not hang the device.
    r->n = (int)clamp(ceil((r->t1 - r->t0) / r->step), 0.0f, 16777216.0f);
  }
  return axis;
}

#endif
