// The three ways of marching a ray (MODE): each returns the pixel colour and adds the
// volume samples it took to *count. With ESS they ask skip.cl before each cell and leap
// the samples that cannot change the pixel, so the image is the same with or without it.
#ifndef VOXRAY_MARCH_CL
#define VOXRAY_MARCH_CL

#include "classification/gradient_opacity.cl"
#include "classification/labels.cl"
#include "classification/lut.cl"
#include "classification/overlay.cl"
#include "classification/preint.cl"
#include "classification/surfaces.cl"
#include "classification/tf2d.cl"
#include "empty_space/skip.cl"
#include "math.cl"
#include "reconstruction/gradients.cl"
#include "reconstruction/sampling.cl"
#include "shading/shading.cl"
#if HIT_OUTPUT
#include "march/hit_output.cl"
#endif

// Normal at p (voxel coordinates) in world space; not normalised.
inline float3 world_gradient(VOLUME_ARG, __constant RaycastParams* P, float3 p) {
  float3 g = volume_gradient(VOLUME, P, p);
  return mat_mul(P->grad_x, P->grad_y, P->grad_z, g);
}

// First hit of the iso range, refined by bisection between the last miss and the hit.
// *hit_out (kept by HIT_OUTPUT variants): the hit in voxel coordinates, w 1 for a
// crossing, 0 for the first sample (entry face or clip cap); untouched without a hit.
inline float3 march_iso(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                        CELL_ARGS, const Ray* r, float3 origin_w, float3 dir_w, int axis,
                        uint* count, float4* hit_out) {
  int hit = -1;
  float t_hit = 0.0f;
  for (int i = 0, check = 0; i <= r->n; ++i) {
    if (ESS && i >= check) {
      i = ess_leap(leap, range, P, r, false, i, &check);
      if (i > r->n) break;
    }
    float t = ray_sample_t(r, i);
    ++*count;
    if (in_iso(P, sample_volume(VOLUME, P, r->o + t * r->d))) {
      hit = i;
      t_hit = t;
      break;
    }
  }
  if (hit < 0) return P->background.xyz;
  if (hit > 0) {
    float a = ray_sample_t(r, hit - 1), b = t_hit;
    for (int k = 0; k < REFINE_STEPS; ++k) {
      float m = 0.5f * (a + b);
      if (in_iso(P, sample_volume(VOLUME, P, r->o + m * r->d)))
        b = m;
      else
        a = m;
    }
    *count += REFINE_STEPS;
    t_hit = REFINE_STEPS > 0 ? 0.5f * (a + b) : b;
  }
  float3 p_v = r->o + t_hit * r->d;
  *hit_out = (float4)(p_v, hit > 0 ? 1.0f : 0.0f);
  float4 c = lut_lookup(lut, P, sample_volume(VOLUME, P, p_v));
  if (!SHADING) return c.xyz;
  float3 n_w;
  if (hit == 0 && axis >= 0) {
    // The ray starts inside the surface at a clip face: shade the cut as a flat cap.
    float3 e = (float3)(axis == 0, axis == 1, axis == 2);
    n_w = mat_mul(P->grad_x, P->grad_y, P->grad_z, e);
  } else {
    n_w = world_gradient(VOLUME, P, p_v);
    *count += GRADIENT_TAPS;
  }
  return shade(c.xyz, n_w, origin_w + t_hit * dir_w, -dir_w, P->light_w, frame_light(lut, P, p_v));
}

#if ADAPTIVE
// Adaptive dvr (ADAPTIVE): segment i grows to ADAPTIVE_STEPS base steps where the level
// (classify.cl, adaptive_level) of the cell holding the long segment's midpoint allows it
// and the short midpoints it replaces stay within one voxel of that midpoint. Only 4: with
// 2 as well (a second lookup per sample) the lookups cost more than the samples saved
// (CT400, VTK's table).
#define ADAPTIVE_STEPS 4

inline bool long_at(__global const uchar* leap, __constant RaycastParams* P, float3 p) {
  int3 c = cell_of(P, p);
  int cells = P->cells.x * P->cells.y * P->cells.z;
  return leap[cells + (c.z * P->cells.y + c.y) * P->cells.x + c.x] != 0;
}

// Whether the rays may take long segments at all: the short midpoints a long segment
// replaces lie within (ADAPTIVE_STEPS - 1) step / 2 of its own, at most a voxel along each
// axis (dmax: voxels per mm along the ray's largest axis).
inline bool adaptive_reach(float step, float dmax) {
  return (ADAPTIVE_STEPS - 1) * 0.5f * step * dmax <= 1.0f;
}

// Segment i, or ADAPTIVE_STEPS of them as one where allowed; *f the steps it spans.
inline float2 adaptive_segment(__global const uchar* leap, __constant RaycastParams* P,
                               const Ray* r, int i, bool reach, int* f) {
  float2 s = ray_segment(r, i);
  float b = ray_segment(r, i + ADAPTIVE_STEPS - 1).y;
  *f = 1;
  if (reach && long_at(leap, P, r->o + 0.5f * (s.x + b) * r->d)) *f = ADAPTIVE_STEPS, s.y = b;
  return s;
}
#endif

#if PREINT
// Segment i's front value (PREINT): the sample of segment i - 1, which the ray took last unless
// a leap (or the ray's start) came between; then it is taken now, so that a leap changes no
// pixel. Segment 0 has none: its own value. *prev_i, *prev_value: the last sample taken.
inline float preint_front(VOLUME_ARG, __constant RaycastParams* P, const Ray* r, int i, float value,
                          int* prev_i, float* prev_value, uint* count) {
  float front = value;
  if (i >= 1) {
    if (*prev_i == i - 1) {
      front = *prev_value;
    } else {
      float2 q = ray_segment(r, i - 1);
      front = sample_volume(VOLUME, P, r->o + 0.5f * (q.x + q.y) * r->d);
      ++*count;
    }
  }
  *prev_i = i;
  *prev_value = value;
  return front;
}
#define PREINT_PARAMS , int i, int *prev_i, float *prev_value
#define PREINT_PASS(i) , i, &prev_i, &prev_value
#else
#define PREINT_PARAMS
#define PREINT_PASS(i)
#endif

// One dvr segment s into the composite; returns true once the ray terminates.
inline bool dvr_segment(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                        const Ray* r, float2 s, float3 origin_w, float3 dir_w, uint* count,
                        float3* acc, float* alpha
#if HIT_OUTPUT
                        ,
                        float4* hit_out
#endif
                            LABEL_PARAMS OVERLAY_PARAMS PREINT_PARAMS) {
  float seg = s.y - s.x;
  if (seg <= 0.0f) return false;  // segment 0 without jitter
  float t = 0.5f * (s.x + s.y);
  float3 p_v = r->o + t * r->d;
  ++*count;
  float value = sample_volume(VOLUME, P, p_v);
#if PREINT
  // The segment's value runs from the previous sample's to this one's; its length over the
  // step the table was made for (opacity correction: otherwise the table's opacity as is).
  float front = preint_front(VOLUME, P, r, i, value, prev_i, prev_value, count);
  float4 c = preint_lookup(lut, P, front, value, OPACITY_CORRECTION ? seg / P->view.z : 1.0f);
#else
  float4 c = lut_lookup(lut, P, value);
#endif
#if SEGMENT_TF
  // The label's own table where it has one (segment_tf.cl), before "transparent" is decided.
  int lab = label_at(labels, P, p_v);
  c = segment_tf(segtf, segs, P, lab, value, c);
#endif
#if OVERLAY
  // The base's classification below (labels, gradient opacity, shading) is its own; the
  // overlay's sample joins it after, unshaded (PET on CT shows as a glow, and the base's
  // gradient says nothing of the overlay's surfaces).
  float4 o =
      overlay_cell(ocells, P, p_v) ? overlay_classify(ovol, olut, ogeo, p_v) : (float4)(0.0f);
#define DVR_NOTHING (c.w <= 0.0f && o.w <= 0.0f)
#else
#define DVR_NOTHING (c.w <= 0.0f)
#endif
  if (DVR_NOTHING) return false;
#if TF2D
  // Colour and opacity from the 2D table at (value, |gradient|) where the colour table (the 2D
  // table's largest over gradient) lets the sample show; the gradient is the one shading uses.
  float3 n_w = (float3)(0.0f);
  if (c.w > 0.0f) {
    n_w = world_gradient(VOLUME, P, p_v);
    *count += GRADIENT_TAPS;
    c = tf2d_lookup(lut, P, value, n_w);
  }
  if (DVR_NOTHING) return false;
#endif
#if LABELS
#if !SEGMENT_TF
  int lab = label_at(labels, P, p_v);
#endif
  c = label_classify(segs, lab, c);
  if (DVR_NOTHING) return false;
#endif
#if GRADIENT_OPACITY
  // The opacity per reference step times the factor at |gradient|, before the correction
  // to the segment's length; the gradient is the one shading uses.
  // (OVERLAY: only where the base shows, as the packets' dvr_gradient_opacityN.)
  float3 n_w = (float3)(0.0f);
  if (c.w > 0.0f) {
    n_w = world_gradient(VOLUME, P, p_v);
    *count += GRADIENT_TAPS;
    c.w *= gradient_opacity(lut, P, n_w);
  }
  if (DVR_NOTHING) return false;
#endif
#undef DVR_NOTHING
  float3 rgb = c.xyz;
#if PREINT
  // Shaded at the middle of the run from the previous sample to this one (the segment's start,
  // half a step back): at this sample instead, a long step's surfaces took their normals from
  // up to a step inside, and CThead lost 1-3 dB against the plain classification.
  t = s.x;
  p_v = r->o + t * r->d;
#endif
  if (SHADING && c.w > 0.0f) {
#if GRADIENT_OPACITY || TF2D
    rgb = shade(rgb, n_w, origin_w + t * dir_w, -dir_w, P->light_w, frame_light(lut, P, p_v));
#else
    rgb = shade(rgb, world_gradient(VOLUME, P, p_v), origin_w + t * dir_w, -dir_w, P->light_w,
                frame_light(lut, P, p_v));
    *count += GRADIENT_TAPS;
#endif
  }
#if OVERLAY
  // Summed extinction: two media in one segment attenuate as the product of their
  // transmittances, 1 - (1 - a_base)(1 - a_overlay) per reference step, and each emits in
  // proportion to its own opacity (colours weighted by opacity). This keeps the rule
  // independent of the step length (the opacity correction of the sum is the product of the
  // corrections), is symmetric in the two volumes, and makes an overlay with nothing to show
  // leave the base's sample as it was (to rounding).
  rgb = (c.w * rgb + o.w * o.xyz) / (c.w + o.w);
  c.w = 1.0f - (1.0f - c.w) * (1.0f - o.w);
#endif
  float a = OPACITY_CORRECTION && !PREINT ? CORRECTED_OPACITY(c.w, seg / P->view.w) : c.w;
  *acc += (1.0f - *alpha) * a * rgb;
#if HIT_OUTPUT
  float before = *alpha;
#endif
  *alpha += (1.0f - *alpha) * a;
#if HIT_OUTPUT
  dvr_hit_crossing(before, *alpha, s, r, hit_out);
#endif
  return *alpha >= P->dvr.z;
}

// Front-to-back emission-absorption over segments, each sampled at its midpoint (ADAPTIVE:
// some segments ADAPTIVE_STEPS base steps long, adaptive_segment).
// *hit_out (HIT_OUTPUT variants): where the accumulated opacity reaches DVR_HIT_ALPHA
// (hit_output.cl); untouched where it does not.
inline float3 march_dvr(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                        CELL_ARGS, const Ray* r, float3 origin_w, float3 dir_w, uint* count
#if HIT_OUTPUT
                        ,
                        float4* hit_out
#endif
                            LABEL_PARAMS OVERLAY_PARAMS SURFACE_PARAMS) {
  float3 acc = (float3)(0.0f);
  float alpha = 0.0f;
#if SURFACES
  // The surface layer of this pixel (one work-item per pixel: the global id is the pixel).
  const size_t pix = (size_t)get_global_id(1) * P->image.x + get_global_id(0);
  const float4 layer = surf[2 * pix];
  const float layer_t = surf[2 * pix + 1].x;
  bool layer_due = layer.w > 0.0f;
#endif
#if HIT_OUTPUT
#define DVR_HIT_ARG , hit_out
#else
#define DVR_HIT_ARG
#endif
#if ADAPTIVE
  bool reach = adaptive_reach(r->step, fmax(fabs(r->d.x), fmax(fabs(r->d.y), fabs(r->d.z))));
#endif
#if PREINT
  int prev_i = -2;  // the last segment sampled, and its value (preint_front)
  float prev_value = 0.0f;
#endif
  for (int i = 0, check = 0, f = 1; i <= r->n; i += f) {  // f: steps segment i spans
    if (ESS && i >= check) {
      i = ess_leap(leap, range, P, r, true, i, &check);
      if (i > r->n) break;
    }
#if ADAPTIVE
    float2 s = adaptive_segment(leap, P, r, i, reach, &f);
#else
    float2 s = ray_segment(r, i);
#endif
#if SURFACES
    if (layer_due && 0.5f * (s.x + s.y) >= layer_t) {
      surface_composite(layer, &acc, &alpha);
      layer_due = false;
      if (alpha >= P->dvr.z) break;
    }
#endif
    if (dvr_segment(VOLUME, P, lut, r, s, origin_w, dir_w, count, &acc,
                    &alpha DVR_HIT_ARG LABEL_PASS OVERLAY_PASS PREINT_PASS(i)))
      break;
  }
#undef DVR_HIT_ARG
#undef PREINT_PARAMS
#undef PREINT_PASS
#if SURFACES
  if (layer_due) surface_composite(layer, &acc, &alpha);  // behind the last sample
#endif
  return acc + (1.0f - alpha) * P->background.xyz;
}

// Maximum intensity, mapped through the grey window. Values at or below the window's low
// end show black whatever they are, so skipping starts from there; a ray that reaches
// the high end is white whatever follows. Neither changes a pixel.
inline float3 march_mip(VOLUME_ARG, __constant RaycastParams* P, CELL_ARGS, const Ray* r,
                        uint* count) {
  float vmax = -FLT_MAX, low = P->dvr.x, high = P->dvr.x + 1.0f / P->dvr.y;
  for (int i = 0, check = 0; i <= r->n && vmax < high; ++i) {
    if (ESS && i >= check) {
      i = ess_next_mip(range, P, r, i, fmax(vmax, low), &check);
      if (i > r->n) break;
    }
    ++*count;
    vmax = fmax(vmax, sample_volume(VOLUME, P, r->o + ray_sample_t(r, i) * r->d));
  }
  return (float3)(clamp((vmax - low) * P->dvr.y, 0.0f, 1.0f));
}

#endif
