// What HIT_OUTPUT variants add for dvr (raycast.cl's hits, for picking in 3D): a ray's
// "first opaque sample", the point where its accumulated opacity first reaches
// DVR_HIT_ALPHA. A ray that never reaches it (or stops earlier, early termination below
// it) has no hit. iso's hit is march_iso's own refined first hit.
#ifndef VOXRAY_HIT_OUTPUT_CL
#define VOXRAY_HIT_OUTPUT_CL

#include "intersection/ray.cl"

// Half: what lies in front hides as much as it shows of what lies behind.
#define DVR_HIT_ALPHA 0.5f

// The point where the accumulated opacity reached DVR_HIT_ALPHA, for a segment [ta, tb]
// over which it went from `before` to `after` (a crossing when before < DVR_HIT_ALPHA <=
// after; then after > before): linear between the segment's ends, where the composite is
// known. Against the analytic depth on a one-voxel opacity ramp at step 0.5 voxel, linear
// was off by at most 0.03 voxel, the segment's own exponential by 0.16 (its midpoint
// sample underestimates a ramp's opacity). A macro so that float and the floatN lanes of
// hit_output_lanes.cl share it.
#define DVR_HIT_T(before, after, ta, tb) \
  ((ta) + ((tb) - (ta)) * (DVR_HIT_ALPHA - (before)) / ((after) - (before)))

// One ray: sets *hit_out (voxel coordinates, w 1) when the segment crosses the threshold.
inline void dvr_hit_crossing(float before, float after, float2 s, const Ray* r, float4* hit_out) {
  if (before < DVR_HIT_ALPHA && after >= DVR_HIT_ALPHA)
    *hit_out = (float4)(r->o + DVR_HIT_T(before, after, s.x, s.y) * r->d, 1.0f);
}

#endif
