// The 2D transfer function's queue for dvr packets (TF2D, dvr_packet.cl), used where the frame
// has no labels, overlay or hit output. A sample's opacity needs its gradient (the 2D table is
// read at (value, |gradient|)); taken in place, each step's gradient call ran with only the
// step's seen lanes useful (about 65 % on CThead, as the shading queue's comment measured), and
// the frame cost 1.3 ... 1.6x the 1D one. So the seen samples wait here, unclassified, until
// LANES of them fill one call: gradient, table, shading and then the composite, entry by entry
// in the order each lane took its samples, as without the queue. A lane's opacity is known only
// at a flush, so it may march a few samples past the point where it terminates; the flush skips
// them (a lane's samples after its opacity reached the termination threshold never count), so
// the image is the in-place one's. Each lane's colour and opacity live here meanwhile.
#ifndef VOXRAY_CLASSIFY_QUEUE_CL
#define VOXRAY_CLASSIFY_QUEUE_CL

#include "classification/lut.cl"
#include "classification/tf2d_lanes.cl"
#include "intersection/ray_lanes.cl"
#include "reconstruction/gradients_lanes.cl"
#include "shading/shading_lanes.cl"
#include "simd/math_lanes.cl"

#if TF2D
typedef struct {
  float t[2 * LANES], value[2 * LANES], seg[2 * LANES];
  int lane[2 * LANES];  // whose ray entry e belongs to
  int n;
  // The part of each lane's ray that differs between lanes (ShadeQueue's, shade_queue.cl).
  float ray[6][LANES];
  float acc[3][LANES], alpha[LANES];  // each lane's composite
} ClassifyQueue;

inline void classify_queue_init(ClassifyQueue* q, const RayPacket* r, const floatN world[6]) {
  floatN ray[6] = {r->ox, r->oy, r->oz, world[0], world[1], world[2]};
  if (!ORTHO)
    ray[0] = r->dx, ray[1] = r->dy, ray[2] = r->dz, ray[3] = world[3], ray[4] = world[4],
    ray[5] = world[5];
  for (int k = 0; k < 6; ++k) vstoreN(ray[k], 0, q->ray[k]);
  // Entries past n still go through the gradient (whole vectors): t = 0 and lane 0 put them
  // at a lane's entry point, in the volume.
  for (int e = 0; e < 2 * LANES; ++e) q->t[e] = q->value[e] = q->seg[e] = 0.0f, q->lane[e] = 0;
  for (int l = 0; l < LANES; ++l) q->acc[0][l] = q->acc[1][l] = q->acc[2][l] = q->alpha[l] = 0.0f;
  q->n = 0;
}

inline floatN classify_lane_valuesN(const float* a, intN lane) {
#define CLASSIFY_LANE_VALUE(l, n) a[lane.s##l]
  return (floatN)(LANE_LIST(CLASSIFY_LANE_VALUE));
#undef CLASSIFY_LANE_VALUE
}

// Classifies, shades and composites the first `count` entries (at most LANES); the rest move to
// the front.
inline void classify_queue_flush(__global const short* restrict vol, __constant RaycastParams* P,
                                 __global const float4* lut, ClassifyQueue* q, int count) {
  floatN t = vloadN(0, q->t);
  intN lane = vloadN(0, q->lane);
  // voxel origin, direction; world origin, direction: the shared part from P
  floatN ray[12];
  float4 shared[4] = {P->eye_v, P->forward_v, P->eye_w, P->forward_w};
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 4; ++s) {
      bool varies = ORTHO ? s % 2 == 0 : s % 2 == 1;  // origins with ORTHO, else directions
      float u = k == 0 ? shared[s].x : k == 1 ? shared[s].y : shared[s].z;
      ray[3 * s + k] = varies ? classify_lane_valuesN(q->ray[3 * (s / 2) + k], lane) : (floatN)(u);
    }
  VecN at = {ray[0] + t * ray[3], ray[1] + t * ray[4], ray[2] + t * ray[5]};
  VecN normal = gradient_to_worldN(P, volume_gradientN(vol, P, at));
  floatN c[4];
  tf2dN(lut, P, vloadN(0, q->value), normal, c);
  floatN a = c[3];
  if (OPACITY_CORRECTION) {
    floatN ratio = vloadN(0, q->seg) / P->view.w;
    a = CORRECTED_OPACITY_BY(a, ratio, fast_log2N, fast_exp2N);
  }
  VecN color = {c[0], c[1], c[2]};
  if (SHADING) {
    VecN pos = {ray[6] + t * ray[9], ray[7] + t * ray[10], ray[8] + t * ray[11]};
    VecN view = {-ray[9], -ray[10], -ray[11]};
    color = shade_frameN(lut, P, at, color, normal, pos, view);
  }
  float as[LANES], cs[3][LANES];
  vstoreN(a, 0, as);
  vstoreN(color.x, 0, cs[0]);
  vstoreN(color.y, 0, cs[1]);
  vstoreN(color.z, 0, cs[2]);
  const float done = P->dvr.z;
  for (int e = 0; e < count; ++e) {
    int l = q->lane[e];
    float before = q->alpha[l];
    if (before >= done) continue;  // the lane ended at an earlier sample
    float w = (1.0f - before) * as[e];
    for (int ch = 0; ch < 3; ++ch) q->acc[ch][l] += w * cs[ch][e];
    q->alpha[l] = before + w;
  }
  int n = q->n;
  for (int e = count; e < n; ++e) {
    q->t[e - count] = q->t[e];
    q->value[e - count] = q->value[e];
    q->seg[e - count] = q->seg[e];
    q->lane[e - count] = q->lane[e];
  }
  q->n = n - count;
}

// Queues the lanes in `seen` (their t, value and segment length); classifies a full call's
// worth when there is one. Returns each lane's opacity so far (what the flushes composited).
inline floatN classify_queue_push(__global const short* restrict vol, __constant RaycastParams* P,
                                  __global const float4* lut, ClassifyQueue* q, floatN t,
                                  floatN value, floatN seg, intN seen) {
  float ts[LANES], vs[LANES], ss[LANES];
  int take[LANES];
  vstoreN(t, 0, ts);
  vstoreN(value, 0, vs);
  vstoreN(seg, 0, ss);
  vstoreN(seen, 0, take);
  // Without branches, as shade_queue_push: n < LANES before, so n + LANES - 1 fits.
  int n = q->n;
  for (int l = 0; l < LANES; ++l) {
    q->t[n] = ts[l], q->value[n] = vs[l], q->seg[n] = ss[l], q->lane[n] = l;
    n += take[l] & 1;
  }
  q->n = n;
  if (n >= LANES) classify_queue_flush(vol, P, lut, q, LANES);
  return vloadN(0, q->alpha);
}

#endif  // TF2D

#endif
