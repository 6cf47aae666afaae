// The shading queue of dvr packets (dvr_packet.cl): seen samples wait here until LANES of
// them fill one gradient-and-shade call. Shading each step's seen lanes in place ran
// calls with 65 % of their lanes useful on average (CThead, VTK's transfer function); the
// gradient's gathers and the shading cost the same for the idle lanes. A sample's weight
// in the composite is known when it is queued (opacity does not depend on shading), so
// only its colour waits: acc[lane] += weight * lit colour, in the order the lane took its
// samples, as without the queue. An entry keeps only t, the value and the weight; its
// position, colour and view come back from its lane's ray at the flush. With
// GRADIENT_OPACITY the weight needs the gradient first (dvr_gradient_opacityN), taken when
// the sample is: the entry keeps it too, so the flush shades without taking it again; so does
// TF2D, whose colour the flush looks up at (value, |gradient|). With
// LABELS the entry keeps its label, whose segment colour the flush mixes in. With PREINT it
// keeps the segment's front value, whose pre-integrated colour the flush looks up.
#ifndef VOXRAY_SHADE_QUEUE_CL
#define VOXRAY_SHADE_QUEUE_CL

#include "classification/labels_lanes.cl"
#include "classification/lut_lanes.cl"
#include "classification/preint_lanes.cl"
#include "classification/segment_tf_lanes.cl"
#include "classification/tf2d_lanes.cl"
#include "intersection/ray_lanes.cl"
#include "reconstruction/gradients_lanes.cl"

#if LABELS
#define QUEUE_SEGS_PARAM , __constant float4* segs SEGTF_PARAMS
#define QUEUE_SEGS_ARG , segs SEGTF_PASS
#else
#define QUEUE_SEGS_PARAM
#define QUEUE_SEGS_ARG
#endif

typedef struct {
  float t[2 * LANES], value[2 * LANES], weight[2 * LANES];
  int lane[2 * LANES];  // whose ray entry e belongs to
#if GRADIENT_OPACITY || TF2D
  float normal[3][2 * LANES];  // each entry's world gradient
#endif
#if LABELS
  int label[2 * LANES];  // each entry's label (its colour, labels_lanes.cl)
#endif
#if PREINT
  float front[2 * LANES];  // each entry's segment's front value (preint_lanes.cl)
#endif
  int n;
  // The part of each lane's ray that differs between lanes: voxel and world origins with
  // ORTHO, else voxel and world directions (pixel_raysN).
  float ray[6][LANES];
  float acc[3][LANES];  // each lane's composited colour
} ShadeQueue;

inline void shade_queue_init(ShadeQueue* q, const RayPacket* r, const floatN world[6]) {
  floatN ray[6] = {r->ox, r->oy, r->oz, world[0], world[1], world[2]};
  if (!ORTHO)
    ray[0] = r->dx, ray[1] = r->dy, ray[2] = r->dz, ray[3] = world[3], ray[4] = world[4],
    ray[5] = world[5];
  for (int k = 0; k < 6; ++k) vstoreN(ray[k], 0, q->ray[k]);
  // Entries past n still go through the gradient (whole vectors): t = 0 and lane 0 put
  // them at a lane's entry point, in the volume.
  for (int e = 0; e < 2 * LANES; ++e) q->t[e] = q->value[e] = q->weight[e] = 0.0f, q->lane[e] = 0;
#if GRADIENT_OPACITY || TF2D
  for (int e = 0; e < 2 * LANES; ++e) q->normal[0][e] = q->normal[1][e] = q->normal[2][e] = 0.0f;
#endif
#if LABELS
  for (int e = 0; e < 2 * LANES; ++e) q->label[e] = 0;
#endif
#if PREINT
  for (int e = 0; e < 2 * LANES; ++e) q->front[e] = 0.0f;
#endif
  for (int c = 0; c < 3; ++c)
    for (int l = 0; l < LANES; ++l) q->acc[c][l] = 0.0f;
  q->n = 0;
}

inline floatN lane_valuesN(const float* a, intN lane) {
#define LANE_VALUE(l, n) a[lane.s##l]
  return (floatN)(LANE_LIST(LANE_VALUE));
#undef LANE_VALUE
}

// Shades the first `count` entries (at most LANES) and adds them to their lanes' colours;
// the rest move to the front.
inline void shade_queue_flush(__global const short* restrict vol, __constant RaycastParams* P,
                              __global const float4* lut, ShadeQueue* q,
                              int count QUEUE_SEGS_PARAM) {
  floatN t = vloadN(0, q->t);
  intN lane = vloadN(0, q->lane);
  // voxel origin, direction; world origin, direction: the shared part from P
  floatN ray[12];
  float4 shared[4] = {P->eye_v, P->forward_v, P->eye_w, P->forward_w};
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 4; ++s) {
      bool varies = ORTHO ? s % 2 == 0 : s % 2 == 1;  // origins with ORTHO, else directions
      float u = k == 0 ? shared[s].x : k == 1 ? shared[s].y : shared[s].z;
      ray[3 * s + k] = varies ? lane_valuesN(q->ray[3 * (s / 2) + k], lane) : (floatN)(u);
    }
  VecN at = {ray[0] + t * ray[3], ray[1] + t * ray[4], ray[2] + t * ray[5]};
  VecN pos = {ray[6] + t * ray[9], ray[7] + t * ray[10], ray[8] + t * ray[11]};
  VecN view = {-ray[9], -ray[10], -ray[11]};
  floatN c[4];
#if TF2D
  VecN kept = {vloadN(0, q->normal[0]), vloadN(0, q->normal[1]), vloadN(0, q->normal[2])};
  tf2dN(lut, P, vloadN(0, q->value), kept, c);
#elif PREINT
  preintN(lut, P, vloadN(0, q->front), vloadN(0, q->value), (floatN)(1.0f), c);  // colour only
#else
  lutN(lut, P, vloadN(0, q->value), c);
#endif
#if SEGMENT_TF
  segment_tfN(segtf, segs, P, vloadN(0, q->label), vloadN(0, q->value), c, 0);
#endif
#if LABELS
  label_colourN(segs, vloadN(0, q->label), c);
#endif
  VecN color = {c[0], c[1], c[2]};
#if GRADIENT_OPACITY || TF2D
  VecN normal = {vloadN(0, q->normal[0]), vloadN(0, q->normal[1]), vloadN(0, q->normal[2])};
#else
  VecN normal = gradient_to_worldN(P, volume_gradientN(vol, P, at));
#endif
  VecN lit = shade_frameN(lut, P, at, color, normal, pos, view);
  floatN w = vloadN(0, q->weight);
  float add[3][LANES];
  vstoreN(w * lit.x, 0, add[0]);
  vstoreN(w * lit.y, 0, add[1]);
  vstoreN(w * lit.z, 0, add[2]);
  for (int e = 0; e < count; ++e)
    for (int ch = 0; ch < 3; ++ch) q->acc[ch][q->lane[e]] += add[ch][e];
  int n = q->n;
  for (int e = count; e < n; ++e) {
    q->t[e - count] = q->t[e];
    q->value[e - count] = q->value[e];
    q->weight[e - count] = q->weight[e];
    q->lane[e - count] = q->lane[e];
#if GRADIENT_OPACITY || TF2D
    for (int k = 0; k < 3; ++k) q->normal[k][e - count] = q->normal[k][e];
#endif
#if LABELS
    q->label[e - count] = q->label[e];
#endif
#if PREINT
    q->front[e - count] = q->front[e];
#endif
  }
  q->n = n - count;
}

// Queues the lanes in `seen` (their t, value and weight, GRADIENT_OPACITY: and gradient);
// shades a full call's worth when there is one.
inline void shade_queue_push(__global const short* restrict vol, __constant RaycastParams* P,
                             __global const float4* lut, ShadeQueue* q, floatN t, floatN value,
                             floatN weight, intN seen
#if GRADIENT_OPACITY || TF2D
                             ,
                             VecN normal
#endif
#if LABELS
                             ,
                             intN label
#endif
                                 QUEUE_SEGS_PARAM
#if PREINT
                             ,
                             floatN front
#endif
) {
  float ts[LANES], vs[LANES], ws[LANES];
  int take[LANES];
  vstoreN(t, 0, ts);
  vstoreN(value, 0, vs);
  vstoreN(weight, 0, ws);
  vstoreN(seen, 0, take);
#if LABELS
  int ls[LANES];
  vstoreN(label, 0, ls);
#endif
#if PREINT
  float fs[LANES];
  vstoreN(front, 0, fs);
#endif
#if GRADIENT_OPACITY || TF2D
  float ns[3][LANES];
  vstoreN(normal.x, 0, ns[0]);
  vstoreN(normal.y, 0, ns[1]);
  vstoreN(normal.z, 0, ns[2]);
#endif
  // Without branches (which lanes are seen is hard to predict): every lane is written at
  // n, and n moves on past the seen ones. n < LANES before, so n + LANES - 1 fits.
  int n = q->n;
  for (int l = 0; l < LANES; ++l) {
    q->t[n] = ts[l], q->value[n] = vs[l], q->weight[n] = ws[l], q->lane[n] = l;
#if GRADIENT_OPACITY || TF2D
    q->normal[0][n] = ns[0][l], q->normal[1][n] = ns[1][l], q->normal[2][n] = ns[2][l];
#endif
#if LABELS
    q->label[n] = ls[l];
#endif
#if PREINT
    q->front[n] = fs[l];
#endif
    n += take[l] & 1;
  }
  q->n = n;
  if (n >= LANES) shade_queue_flush(vol, P, lut, q, LANES QUEUE_SEGS_ARG);
}

#endif
