// The colour and opacity table (the transfer function, baked per frame by
// engine/src/transfer_function.cpp): P->dims.w entries from stored value P->values.z, P->values.w
// entries per stored unit.
#ifndef VOXRAY_LUT_CL
#define VOXRAY_LUT_CL

#include "params.cl"

inline float4 lut_lookup(__global const float4* lut, __constant RaycastParams* P, float v) {
  float last = (float)(P->dims.w - 1);
  float x = clamp((v - P->values.z) * P->values.w, 0.0f, last);
  float i = floor(x);
  int k = (int)i;
  int k1 = min(k + 1, P->dims.w - 1);
  return mix(lut[k], lut[k1], x - i);
}

// iso: whether stored value v lies in the surface's range (P->values.x .. y).
inline bool in_iso(__constant RaycastParams* P, float v) {
  return v >= P->values.x && v <= P->values.y;
}

// Opacity a of a reference-length step, for a segment `ratio` times that length:
// 1 - (1 - a)^ratio, on a fast path (pow costs a fifth of a CPU dvr frame); a = 1 stays
// exactly 1. A macro so that float (native_) and the floatN lanes of
// march_lanes.cl (math_lanes.cl) share it.
#define CORRECTED_OPACITY_BY(a, ratio, LOG2, EXP2) \
  ((a) >= 1.0f ? 1.0f : 1.0f - EXP2((ratio)*LOG2(1.0f - (a))))
#define CORRECTED_OPACITY(a, ratio) CORRECTED_OPACITY_BY(a, ratio, native_log2, native_exp2)

#endif
