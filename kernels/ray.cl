// One ray through the clip box and the positions of its samples, shared by every mode
// and by the empty-space skipping that leaps over them. t is in mm along the ray; the
// position in voxel coordinates is o + t * d.
#ifndef VOXRAY_RAY_CL
#define VOXRAY_RAY_CL

typedef struct {
  float3 o, d;   // origin and direction in voxel coordinates (d per mm)
  float3 inv_d;  // 1 / d, 0 where d is 0 (cell exits never divide by zero)
  float t0, t1;  // clip-box entry and exit
  float step;    // mm between samples
  float j;       // jitter: samples move forward by j steps (0 without JITTER)
  int n;         // ceil((t1 - t0) / step): samples or segments are numbered 0 ... n
} Ray;

// The per-pixel jitter fraction in [0, 1); the formula is spelt out in raycast.cl.
inline float jitter_fraction(int px, int py) {
  uint h = (uint)px * 73856093u ^ (uint)py * 19349663u;
  h = (h ^ (h >> 13)) * 0x5bd1e995u;
  h ^= h >> 15;
  return (float)(h & 0xffffffu) / 16777216.0f;
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

#endif
