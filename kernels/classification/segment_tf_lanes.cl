// segment_tf (segment_tf.cl) for each lane of a packet.
#ifndef VOXRAY_SEGMENT_TF_LANES_CL
#define VOXRAY_SEGMENT_TF_LANES_CL

#include "classification/lut_lanes.cl"
#include "classification/segment_tf.cl"
#include "simd/lanes.cl"

#if SEGMENT_TF
// Where a lane's label LAB has its own table: its channels from..3 of c (3: the opacity only,
// 0: colour and opacity) from that table at the lane's value V.
inline void segment_tfN(__global const float4* segtf, __constant float4* segs,
                        __constant RaycastParams* P, intN lab, floatN v, floatN c[4], int from) {
#define SLOT_LANE(l, n) segment_tf_slot(segs, lab.s##l)
  intN slot = (intN)(LANE_LIST(SLOT_LANE));
#undef SLOT_LANE
  intN own = slot > 0;
  if (!any(own)) return;
  intN k, k1;
  floatN f;
  lut_spotN(P, v, &k, &k1, &f);
  intN base = max(slot - 1, 0) * P->dims.w;  // packets: tables under 2^31 entries
  k += base;
  k1 += base;
  float4 e[LANES];
#define SEGTF_LANE(l, n) e[n] = mix(segtf[k.s##l], segtf[k1.s##l], f.s##l);
#define SEGTF_X(l, n) e[n].x
#define SEGTF_Y(l, n) e[n].y
#define SEGTF_Z(l, n) e[n].z
#define SEGTF_W(l, n) e[n].w
  LANE_EACH(SEGTF_LANE)
  floatN t[4] = {(floatN)(LANE_LIST(SEGTF_X)), (floatN)(LANE_LIST(SEGTF_Y)),
                 (floatN)(LANE_LIST(SEGTF_Z)), (floatN)(LANE_LIST(SEGTF_W))};
  for (int ch = from; ch < 4; ++ch) c[ch] = select(c[ch], t[ch], own);
#undef SEGTF_LANE
#undef SEGTF_X
#undef SEGTF_Y
#undef SEGTF_Z
#undef SEGTF_W
}
#endif

#endif
