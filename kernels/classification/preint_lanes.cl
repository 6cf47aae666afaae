// preint_lookup (preint.cl) for each lane of a packet.
#ifndef VOXRAY_PREINT_LANES_CL
#define VOXRAY_PREINT_LANES_CL

#include "classification/preint.cl"
#include "reconstruction/sampling_lanes.cl"
#include "simd/math_lanes.cl"

// Compiled only where used; the includes above are expanded regardless of #if
// (engine/src/kernel_source.cpp), so they stay outside.
#if PREINT
// Where each lane falls in the table: the four entries' indices (row i: k00, k01; row i + 1:
// k10, k11), the weights along the back value (*fx) and the front value (*fy), and the share
// of the run inside the table (*inside, preint_lookup).
inline void preint_spotN(__constant RaycastParams* P, floatN vf, floatN vb, intN* k00, intN* k01,
                         intN* k10, intN* k11, floatN* fx, floatN* fy, floatN* inside) {
  const float last = (float)(VOXRAY_PREINT_VALUES - 1);
  floatN xf = (vf - P->preint.x) * P->preint.y, xb = (vb - P->preint.x) * P->preint.y;
  floatN cf = clamp(xf, 0.0f, last), cb = clamp(xb, 0.0f, last);
  floatN f0 = floor(cf), b0 = floor(cb);
  *fy = cf - f0;
  *fx = cb - b0;
  intN i = convert_intN(f0), j = convert_intN(b0);
  intN i1 = min(i + 1, (intN)(VOXRAY_PREINT_VALUES - 1));
  intN j1 = min(j + 1, (intN)(VOXRAY_PREINT_VALUES - 1));
  *k00 = i * VOXRAY_PREINT_VALUES + j;
  *k01 = i * VOXRAY_PREINT_VALUES + j1;
  *k10 = i1 * VOXRAY_PREINT_VALUES + j;
  *k11 = i1 * VOXRAY_PREINT_VALUES + j1;
  floatN run = fabs(xb - xf);
  *inside = select((floatN)(1.0f), fabs(cb - cf) / run, run > 0.0f);
}

// Only the opacity: four gathers (with shading the colour is looked up when it shades).
inline floatN preint_alphaN(__global const float4* lut, __constant RaycastParams* P, floatN vf,
                            floatN vb, floatN ratio) {
  intN k00, k01, k10, k11;
  floatN fx, fy, inside;
  preint_spotN(P, vf, vb, &k00, &k01, &k10, &k11, &fx, &fy, &inside);
  __global const float* depth = (__global const float*)(lut + P->dims.w) + 3;
  floatN a = mix(gather_floatN(depth, 4 * k00), gather_floatN(depth, 4 * k01), fx);
  floatN b = mix(gather_floatN(depth, 4 * k10), gather_floatN(depth, 4 * k11), fx);
  return 1.0f - fast_exp2N(-mix(a, b, fy) * inside * ratio);
}

// preint_lookup for each lane, as four channels (lutN of lut_lanes.cl).
inline void preintN(__global const float4* lut, __constant RaycastParams* P, floatN vf, floatN vb,
                    floatN ratio, floatN rgba[4]) {
  intN k00, k01, k10, k11;
  floatN fx, fy, inside;
  preint_spotN(P, vf, vb, &k00, &k01, &k10, &k11, &fx, &fy, &inside);
  __global const float4* t = lut + P->dims.w;
  float4 e[LANES];
#define PREINT_LANE(l, n)                                                                    \
  e[n] = mix(mix(t[k00.s##l], t[k01.s##l], fx.s##l), mix(t[k10.s##l], t[k11.s##l], fx.s##l), \
             fy.s##l);
#define PREINT_X(l, n) e[n].x
#define PREINT_Y(l, n) e[n].y
#define PREINT_Z(l, n) e[n].z
#define PREINT_W(l, n) e[n].w
  LANE_EACH(PREINT_LANE)
  rgba[0] = (floatN)(LANE_LIST(PREINT_X));
  rgba[1] = (floatN)(LANE_LIST(PREINT_Y));
  rgba[2] = (floatN)(LANE_LIST(PREINT_Z));
  rgba[3] = 1.0f - fast_exp2N(-(floatN)(LANE_LIST(PREINT_W)) * inside * ratio);
#undef PREINT_LANE
#undef PREINT_X
#undef PREINT_Y
#undef PREINT_Z
#undef PREINT_W
}

#endif  // PREINT

#endif
