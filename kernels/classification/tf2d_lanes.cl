// tf2d_lookup (tf2d.cl) for each lane of a packet.
#ifndef VOXRAY_TF2D_LANES_CL
#define VOXRAY_TF2D_LANES_CL

#include "classification/tf2d.cl"
#include "reconstruction/sampling_lanes.cl"
#include "shading/shading_lanes.cl"

// Compiled only where used; the includes above are expanded regardless of #if
// (engine/src/kernel_source.cpp), so they stay outside.
#if TF2D
// Where each lane falls in the table: the four entries' indices (row j: k00, k01; row j + 1:
// k10, k11) and the weights along value (*fx) and gradient (*fy).
inline void tf2d_spotN(__constant RaycastParams* P, floatN v, VecN g_w, intN* k00, intN* k01,
                       intN* k10, intN* k11, floatN* fx, floatN* fy) {
  floatN x = clamp((v - P->tf2d.x) * P->tf2d.y, 0.0f, (float)(VOXRAY_TF2D_VALUES - 1));
  floatN y = fmin(sqrt(dotN(g_w, g_w)) * P->tf2d.z, (float)(VOXRAY_TF2D_GRADIENTS - 1));
  floatN x0 = floor(x), y0 = floor(y);
  *fx = x - x0;
  *fy = y - y0;
  intN i = convert_intN(x0), j = convert_intN(y0);
  intN i1 = min(i + 1, (intN)(VOXRAY_TF2D_VALUES - 1));
  intN j1 = min(j + 1, (intN)(VOXRAY_TF2D_GRADIENTS - 1));
  *k00 = j * VOXRAY_TF2D_VALUES + i;
  *k01 = j * VOXRAY_TF2D_VALUES + i1;
  *k10 = j1 * VOXRAY_TF2D_VALUES + i;
  *k11 = j1 * VOXRAY_TF2D_VALUES + i1;
}

// Only the opacity: four gathers (with shading the colour is looked up when it shades).
inline floatN tf2d_alphaN(__global const float4* lut, __constant RaycastParams* P, floatN v,
                          VecN g_w) {
  intN k00, k01, k10, k11;
  floatN fx, fy;
  tf2d_spotN(P, v, g_w, &k00, &k01, &k10, &k11, &fx, &fy);
  __global const float* alpha = (__global const float*)(lut + P->dims.w) + 3;
  floatN a = mix(gather_floatN(alpha, 4 * k00), gather_floatN(alpha, 4 * k01), fx);
  floatN b = mix(gather_floatN(alpha, 4 * k10), gather_floatN(alpha, 4 * k11), fx);
  return mix(a, b, fy);
}

// tf2d_lookup for each lane, as four channels (lutN of lut_lanes.cl).
inline void tf2dN(__global const float4* lut, __constant RaycastParams* P, floatN v, VecN g_w,
                  floatN rgba[4]) {
  intN k00, k01, k10, k11;
  floatN fx, fy;
  tf2d_spotN(P, v, g_w, &k00, &k01, &k10, &k11, &fx, &fy);
  __global const float4* t = lut + P->dims.w;
  float4 e[LANES];
#define TF2D_LANE(l, n)                                                                      \
  e[n] = mix(mix(t[k00.s##l], t[k01.s##l], fx.s##l), mix(t[k10.s##l], t[k11.s##l], fx.s##l), \
             fy.s##l);
#define TF2D_X(l, n) e[n].x
#define TF2D_Y(l, n) e[n].y
#define TF2D_Z(l, n) e[n].z
#define TF2D_W(l, n) e[n].w
  LANE_EACH(TF2D_LANE)
  rgba[0] = (floatN)(LANE_LIST(TF2D_X));
  rgba[1] = (floatN)(LANE_LIST(TF2D_Y));
  rgba[2] = (floatN)(LANE_LIST(TF2D_Z));
  rgba[3] = (floatN)(LANE_LIST(TF2D_W));
#undef TF2D_LANE
#undef TF2D_X
#undef TF2D_Y
#undef TF2D_Z
#undef TF2D_W
}

#endif  // TF2D

#endif
