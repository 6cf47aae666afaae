// march_dvr (march.cl) for a packet of rays (march_lanes.cl): front-to-back compositing
// lane by lane, the seen samples shaded from a queue (shade_queue.cl).
#ifndef VOXRAY_DVR_PACKET_CL
#define VOXRAY_DVR_PACKET_CL

#include "classification/gradient_opacity_lanes.cl"
#include "classification/labels_lanes.cl"
#include "classification/lut_lanes.cl"
#include "classification/preint_lanes.cl"
#include "classification/segment_tf_lanes.cl"
#include "classification/tf2d_lanes.cl"
#include "empty_space/skip_lanes.cl"
#include "intersection/ray_lanes.cl"
#include "march/march_lanes.cl"
#include "reconstruction/sampling_lanes.cl"
#include "shading/classify_queue.cl"
#include "shading/shade_queue.cl"
#include "simd/math_lanes.cl"

// TF2D frames without labels, an overlay or hit output classify their samples from a queue
// (classify_queue.cl says why); the others in place (dvr_tf2dN below). SURFACES inserts
// its layer by the composite's opacity now, which the classify queue holds back.
#define DVR_CLASSIFY_QUEUE (TF2D && !LABELS && !OVERLAY && !HIT_OUTPUT && !SURFACES)

#if GRADIENT_OPACITY
// The lanes in `live` whose table opacity is above 0 take their gradient at t now (their
// opacity, which the composite needs, depends on it): c[3] times the factor at |gradient|
// (dvr_segment of march.cl); *normal keeps the gradient for shading (the queue stores it).
inline void dvr_gradient_opacityN(__global const short* restrict vol, __constant RaycastParams* P,
                                  __global const float4* lut, const RayPacket* r, intN live,
                                  floatN t, floatN c[4], VecN* normal, intN* samples) {
  intN seen = live & (c[3] > 0.0f);
  if (!any(seen)) return;
  VecN at = {r->ox + t * r->dx, r->oy + t * r->dy, r->oz + t * r->dz};
  *normal = gradient_to_worldN(P, volume_gradientN(vol, P, at));
  c[3] *= gradient_opacityN(lut, P, *normal);
  *samples += select((intN)(0), (intN)(GRADIENT_TAPS), seen);
}
#endif

#if TF2D
// The lanes in `live` whose colour-table opacity (the 2D table's largest over gradient) is
// above 0 take their gradient at t now and their opacity (and, unshaded, colour) from the 2D
// table at (value, |gradient|) (dvr_segment of march.cl); *normal keeps the gradient for
// shading (the queue stores it, and its flush looks the colour up with it).
inline void dvr_tf2dN(__global const short* restrict vol, __constant RaycastParams* P,
                      __global const float4* lut, const RayPacket* r, intN live, floatN t,
                      floatN value, floatN c[4], VecN* normal, intN* samples) {
  intN seen = live & (c[3] > 0.0f);
  if (!any(seen)) return;
  VecN at = {r->ox + t * r->dx, r->oy + t * r->dy, r->oz + t * r->dz};
  *normal = gradient_to_worldN(P, volume_gradientN(vol, P, at));
  if (SHADING) {
    c[3] = select(c[3], tf2d_alphaN(lut, P, value, *normal), seen);
  } else {
    floatN e[4];
    tf2dN(lut, P, value, *normal, e);
    for (int ch = 0; ch < 4; ++ch) c[ch] = select(c[ch], e[ch], seen);
  }
  *samples += select((intN)(0), (intN)(GRADIENT_TAPS), seen);
}
#endif

#if PREINT
// The front value of each lane's segment `at` (preint_front of march.cl): the last sample the
// lane took where that was segment at - 1, else (a leap, or the ray's start) segment at - 1's
// sample taken now for the lanes in `live`; segment 0 its own value.
inline floatN preint_frontN(__global const short* restrict vol, __constant RaycastParams* P,
                            const RayPacket* r, intN at, float step, intN live, intN prev_at,
                            floatN prev_value, floatN value, intN* samples) {
  intN follows = prev_at == at - 1;
  floatN front = select(value, prev_value, follows);
  intN need = live & ~follows & (at >= 1);
  if (any(need)) {
    floatN a, b;
    segmentN(r, at - 1, step, &a, &b);
    floatN t = 0.5f * (a + b);
    front = select(front, sampleN(vol, P, r->ox + t * r->dx, r->oy + t * r->dy, r->oz + t * r->dz),
                   need);
    *samples -= need;
  }
  return front;
}
#define DVR_FRONT_PARAM , floatN front
#define DVR_FRONT_ARG(f) , f
#else
#define DVR_FRONT_PARAM
#define DVR_FRONT_ARG(f)
#endif

#if GRADIENT_OPACITY || TF2D
#define DVR_NORMAL_PARAM , VecN normal
#define DVR_NORMAL_ARG(n) , n
#else
#define DVR_NORMAL_PARAM
#define DVR_NORMAL_ARG(n)
#endif

#if LABELS
// Each lane's label, which the shading queue keeps for the colour it looks up at the flush.
#define DVR_LABEL_PARAM , intN label
#define DVR_LABEL_ARG(l) , l
#else
#define DVR_LABEL_PARAM
#define DVR_LABEL_ARG(l)
#endif

#if OVERLAY
// overlay_classify (overlay.cl) lane by lane for the lanes in `live` (transparent for the
// others): the overlay's grid is not the rays', so its reads are gathers anyway.
inline void overlay_classifyN(__global const short* restrict ovol,
                              __global const float4* restrict olut,
                              __global const uchar* restrict ocells, __constant float4* ogeo,
                              __constant RaycastParams* P, floatN x, floatN y, floatN z, intN live,
                              floatN o[4]) {
  float xs[LANES], ys[LANES], zs[LANES], os[4][LANES];
  int ls[LANES];
  vstoreN(x, 0, xs);
  vstoreN(y, 0, ys);
  vstoreN(z, 0, zs);
  vstoreN(live, 0, ls);
  for (int l = 0; l < LANES; ++l) {
    float4 v = (float4)(0.0f);
    const float3 p = (float3)(xs[l], ys[l], zs[l]);
    if (ls[l] && overlay_cell(ocells, P, p)) v = overlay_classify(ovol, olut, ogeo, p);
    os[0][l] = v.x, os[1][l] = v.y, os[2][l] = v.z, os[3][l] = v.w;
  }
  for (int ch = 0; ch < 4; ++ch) o[ch] = vloadN(0, os[ch]);
}
#define DVR_OVERLAY_PARAM , const floatN oc[4]
#define DVR_OVERLAY_ARG(o) , o
#else
#define DVR_OVERLAY_PARAM
#define DVR_OVERLAY_ARG(o)
#endif

// One dvr sample into the composite: opacity (and colour) c of the segment of length seg
// at t, for the lanes in `live`. Updates alpha, active, samples and the colour (acc, or
// the shading queue). GRADIENT_OPACITY: c[3] already scaled, normal its gradient.
inline void dvr_compositeN(__global const short* restrict vol, __constant RaycastParams* P,
                           __global const float4* lut, ShadeQueue* queue, floatN acc[3],
                           floatN* alpha, intN* active, intN* samples, intN live, floatN seg,
                           floatN t, floatN value,
                           const floatN c[4] DVR_NORMAL_PARAM DVR_LABEL_PARAM QUEUE_SEGS_PARAM
                               DVR_OVERLAY_PARAM DVR_FRONT_PARAM) {
  *samples -= live;
#if OVERLAY
  // march.cl's dvr_segment: summed extinction, each volume's colour weighted by its opacity.
  // The base's share of the weight goes to the shading queue, the overlay's (unshaded)
  // straight into acc, which the queue's colours join at the end.
  intN seen = live & ((c[3] > 0.0f) | (oc[3] > 0.0f));
  if (!any(seen)) return;
  floatN a = 1.0f - (1.0f - c[3]) * (1.0f - oc[3]);
  floatN base_share = c[3] / fmax(c[3] + oc[3], 1e-30f);  // 0, not NaN, where neither shows
#else
  intN seen = live & (c[3] > 0.0f);
  if (!any(seen)) return;
  floatN a = c[3];
#endif
  if (OPACITY_CORRECTION && !PREINT) {  // PREINT: built into its table
    floatN ratio = seg / P->view.w;
    a = CORRECTED_OPACITY_BY(a, ratio, fast_log2N, fast_exp2N);
  }
  floatN w = select((floatN)(0.0f), (1.0f - *alpha) * a, seen);
#if OVERLAY
  floatN w_base = w * base_share;
  for (int ch = 0; ch < 3; ++ch) acc[ch] += (w - w_base) * oc[ch];
  intN shaded = seen & (c[3] > 0.0f);
#else
  floatN w_base = w;
  intN shaded = seen;
#endif
  if (SHADING) {
    // PREINT: shaded at the middle of the run from the previous sample (dvr_segment says why).
    shade_queue_push(vol, P, lut, queue, PREINT ? t - 0.5f * seg : t, value, w_base,
                     shaded DVR_NORMAL_ARG(normal) DVR_LABEL_ARG(label)
                         QUEUE_SEGS_ARG DVR_FRONT_ARG(front));
#if !GRADIENT_OPACITY && !TF2D
    *samples += select((intN)(0), (intN)(GRADIENT_TAPS), shaded);
#endif
  } else {
    for (int ch = 0; ch < 3; ++ch) acc[ch] += w_base * c[ch];
  }
  *alpha += w;
  *active &= ~(seen & (*alpha >= P->dvr.z));
}

#if SURFACES
// Each lane's pixel's surface layer (surfaces.cl): premultiplied colour and opacity lc, depth
// lt; lanes past the image's edge get none.
inline void surface_layerN(__constant RaycastParams* P, __global const float4* restrict surf,
                           int gx, int gy, floatN lc[4], floatN* lt) {
  float cs[4][LANES], ts[LANES];
  for (int l = 0; l < LANES; ++l) {
    int px = 4 * gx + (l & 3), py = PACKET_ROWS * gy + (l >> 2);
    float4 c = (float4)(0.0f);
    float t = SURFACE_NONE;
    if (px < P->image.x && py < P->image.y) {
      size_t pix = (size_t)py * P->image.x + px;
      c = surf[2 * pix];
      t = surf[2 * pix + 1].x;
    }
    cs[0][l] = c.x, cs[1][l] = c.y, cs[2][l] = c.z, cs[3][l] = c.w, ts[l] = t;
  }
  for (int ch = 0; ch < 4; ++ch) lc[ch] = vloadN(0, cs[ch]);
  *lt = vloadN(0, ts);
}

// surface_composite (surfaces.cl) for the lanes in `now`, which then have their layer.
inline void surface_compositeN(const floatN lc[4], intN now, floatN acc[3], floatN* alpha,
                               intN* due) {
  floatN w = select((floatN)(0.0f), 1.0f - *alpha, now);
  for (int ch = 0; ch < 3; ++ch) acc[ch] += w * lc[ch];
  *alpha += w * lc[3];
  *due &= ~now;
}
#endif

#if ADAPTIVE
// adaptive_segment (march.cl) for the lanes in `live` (f 1 for the others), `reach` as
// adaptive_reach's for each lane.
inline void adaptive_segmentN(__global const uchar* leap, __constant RaycastParams* P,
                              const RayPacket* r, intN i, float step, intN live, intN reach,
                              floatN* a, floatN* b, intN* f) {
  floatN b4, unused;
  segmentN(r, i, step, a, b);
  segmentN(r, i + ADAPTIVE_STEPS - 1, step, &unused, &b4);
  intN cx, cy, cz;
  intN k = cellN(P, r, 0.5f * (*a + b4), live & reach, &cx, &cy, &cz);
  __global const uchar* level = leap + P->cells.x * P->cells.y * P->cells.z;
#define LEVEL_LANE(l, n) level[k.s##l]
  intN longer = live & reach & (convert_intN((ucharN)(LANE_LIST(LEVEL_LANE))) != 0);
#undef LEVEL_LANE
  *f = select((intN)(1), (intN)(ADAPTIVE_STEPS), longer);
  *b = select(*b, b4, longer);
}

// adaptive_reach (march.cl) for each lane.
inline intN adaptive_reachN(const RayPacket* r, float step) {
  floatN dmax = fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  return (ADAPTIVE_STEPS - 1) * 0.5f * step * dmax <= 1.0f;
}
#endif

// march_dvr (march.cl) for a packet: the same segments, leaps, opacity and early
// termination lane by lane. Seen samples are shaded LANES at a time (shade_queue.cl).
// DVR_BATCH (switches.h) samples per iteration: the later ones' loads need not wait for the
// first's compositing (a lane that ends early drops the rest).
inline void dvr_packet(PACKET_ARGS) {
  float step = P->view.z;
  RayPacket r;
  floatN world[6];
  pixel_raysN(P, gx, gy, &r, world);
  floatN acc[3] = {0.0f, 0.0f, 0.0f}, alpha = 0.0f;
  intN i = 0, check = 0, samples = 0;
  intN active = r.n >= 0;
#if DVR_CLASSIFY_QUEUE
  ClassifyQueue cq;
  classify_queue_init(&cq, &r, world);
#else
  ShadeQueue queue;
  if (SHADING) shade_queue_init(&queue, &r, world);
#endif
#if ADAPTIVE
  intN reach = adaptive_reachN(&r, step);  // long segments allowed (ADAPTIVE)
#endif
#if HIT_OUTPUT
  floatN t_hit = 0.0f;
  intN found = 0;
#endif
#if PREINT
  intN prev_at = -2;  // each lane's last segment sampled, and its value (preint_frontN)
  floatN prev_value = 0.0f;
#endif
#if SURFACES
  floatN layer[4], layer_t;
  surface_layerN(P, surf, gx, gy, layer, &layer_t);
  intN layer_due = layer[3] > 0.0f;
#endif
  while (any(active)) {
    if (ESS) {
      // Waiting for every lane took 3 % less CPU time than iso's half (CThead, VTK's
      // transfer function, both orbits).
      active = leap_packetN(leap, range, P, &r, (intN)(0), &i, &check, active, step, true, true);
      if (!any(active)) break;
    }
    floatN sa[DVR_BATCH], sb[DVR_BATCH], t[DVR_BATCH], value[DVR_BATCH], c[DVR_BATCH][4];
    intN live[DVR_BATCH];
#if LABELS
    intN lab[DVR_BATCH];
#endif
#if OVERLAY
    floatN oc[DVR_BATCH][4];
#endif
#if TF2D
    VecN tf2d_normal[DVR_BATCH];
#endif
#if PREINT
    floatN front[DVR_BATCH];
#endif
    intN at = i;
    for (int k = 0; k < DVR_BATCH; ++k) {
#if ADAPTIVE
      intN f;
      adaptive_segmentN(leap, P, &r, at, step, active & (at <= r.n), reach, &sa[k], &sb[k], &f);
#else
      const int f = 1;
      segmentN(&r, at, step, &sa[k], &sb[k]);
#endif
      live[k] = active & (at <= r.n) & (sb[k] - sa[k] > 0.0f);  // segment 0 without jitter is empty
      at += f;
      t[k] = 0.5f * (sa[k] + sb[k]);
      value[k] = sampleN(vol, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy, r.oz + t[k] * r.dz);
#if PREINT
      // Segments at, at + 1, ...: the first's front may need a sample, the others' is the one
      // before in the batch (no ADAPTIVE: f is 1).
      front[k] = k == 0 ? preint_frontN(vol, P, &r, at - f, step, live[k], prev_at, prev_value,
                                        value[k], &samples)
                        : value[k - 1];
      floatN ratio = OPACITY_CORRECTION ? (sb[k] - sa[k]) / step : (floatN)(1.0f);
      if (SHADING)
        c[k][3] = preint_alphaN(lut, P, front[k], value[k], ratio);
      else
        preintN(lut, P, front[k], value[k], ratio, c[k]);
#else
      if (SHADING)
        c[k][3] = lut_alphaN(lut, P, value[k]);
      else
        lutN(lut, P, value[k], c[k]);
#endif
#if TF2D && !DVR_CLASSIFY_QUEUE
      VecN none = {0.0f, 0.0f, 0.0f};
      tf2d_normal[k] = none;
      dvr_tf2dN(vol, P, lut, &r, live[k], t[k], value[k], c[k], &tf2d_normal[k], &samples);
#endif
#if LABELS
      // label_classify (labels.cl): the opacity now, the colour now or at the queue's flush.
      // Lanes the table leaves transparent stay so (factors are at most 1): when all are,
      // the labels are not read.
      lab[k] = 0;
#if SEGMENT_TF
      // Every lane's label first: its own table (segment_tf.cl) may show what the volume's
      // leaves transparent. Shaded, only the opacity now (the flush looks the colour up).
      lab[k] = label_atN(labels, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy, r.oz + t[k] * r.dz);
      segment_tfN(segtf, segs, P, lab[k], value[k], c[k], SHADING ? 3 : 0);
#endif
      if (any(c[k][3] > 0.0f)) {
#if !SEGMENT_TF
        lab[k] = label_atN(labels, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy, r.oz + t[k] * r.dz);
#endif
        c[k][3] *= label_opacityN(segs, lab[k]);
        if (!SHADING) label_colourN(segs, lab[k], c[k]);
      }
#endif
#if OVERLAY
      overlay_classifyN(ovol, olut, ocells, ogeo, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy,
                        r.oz + t[k] * r.dz, live[k], oc[k]);
#endif
    }
    for (int k = 0; k < DVR_BATCH; ++k) {
#if DVR_CLASSIFY_QUEUE
      // dvr_compositeN's count (one sample per live lane, the gradient's taps per seen one);
      // the composite waits in the queue.
      intN live_k = live[k] & active;
      intN seen = live_k & (c[k][3] > 0.0f);
      samples -= live_k;
      samples += select((intN)(0), (intN)(GRADIENT_TAPS), seen);
      alpha = classify_queue_push(vol, P, lut, &cq, t[k], value[k], sb[k] - sa[k], seen);
      active &= ~(alpha >= P->dvr.z);
#else
#if SURFACES
      // The layer before the first sample at or beyond its depth (march_dvr's rule).
      intN layer_now = layer_due & live[k] & active & (t[k] >= layer_t);
      if (any(layer_now)) {
        surface_compositeN(layer, layer_now, acc, &alpha, &layer_due);
        active &= ~(layer_now & (alpha >= P->dvr.z));
      }
#endif
#if HIT_OUTPUT
      floatN before = alpha;
#endif
#if GRADIENT_OPACITY
      VecN normal = {0.0f, 0.0f, 0.0f};
      dvr_gradient_opacityN(vol, P, lut, &r, live[k] & active, t[k], c[k], &normal, &samples);
#elif TF2D
      VecN normal = tf2d_normal[k];
#endif
      dvr_compositeN(vol, P, lut, &queue, acc, &alpha, &active, &samples, live[k] & active,
                     sb[k] - sa[k], t[k], value[k],
                     c[k] DVR_NORMAL_ARG(normal) DVR_LABEL_ARG(lab[k])
                         QUEUE_SEGS_ARG DVR_OVERLAY_ARG(oc[k]) DVR_FRONT_ARG(front[k]));
#if HIT_OUTPUT
      dvr_hit_crossingN(before, alpha, sa[k], sb[k], &t_hit, &found);
#endif
#endif  // DVR_CLASSIFY_QUEUE
    }
#if PREINT
    prev_at = at - 1;
    prev_value = value[DVR_BATCH - 1];
#endif
    i = at;
    active &= i <= r.n;
  }
#if SURFACES
  if (any(layer_due)) surface_compositeN(layer, layer_due, acc, &alpha, &layer_due);  // behind
#endif
#if DVR_CLASSIFY_QUEUE
  if (cq.n > 0) classify_queue_flush(vol, P, lut, &cq, cq.n);  // n < LANES after a push
  for (int ch = 0; ch < 3; ++ch) acc[ch] = vloadN(0, cq.acc[ch]);
  alpha = vloadN(0, cq.alpha);
#else
  if (SHADING) {
    if (queue.n > 0) shade_queue_flush(vol, P, lut, &queue, queue.n QUEUE_SEGS_ARG);
#if OVERLAY || SURFACES
    // acc holds the overlay's part, or the surface layers': the queue's colours join them.
    for (int ch = 0; ch < 3; ++ch) acc[ch] += vloadN(0, queue.acc[ch]);
#else
    for (int ch = 0; ch < 3; ++ch) acc[ch] = vloadN(0, queue.acc[ch]);
#endif
  }
#endif
  VecN color = {acc[0] + (1.0f - alpha) * P->background.x,
                acc[1] + (1.0f - alpha) * P->background.y,
                acc[2] + (1.0f - alpha) * P->background.z};
#if HIT_OUTPUT
  write_hits_packet(P, hits, gx, gy, r.ox + t_hit * r.dx, r.oy + t_hit * r.dy, r.oz + t_hit * r.dz,
                    select((floatN)(-1.0f), (floatN)(1.0f), found));
#endif
  write_packet(P, out, count, gx, gy, color, samples);
}

#undef DVR_NORMAL_PARAM
#undef DVR_NORMAL_ARG
#undef DVR_LABEL_PARAM
#undef DVR_LABEL_ARG
#undef DVR_OVERLAY_PARAM
#undef DVR_OVERLAY_ARG
#undef DVR_FRONT_PARAM
#undef DVR_FRONT_ARG
#undef DVR_CLASSIFY_QUEUE

#endif
