// gradient_opacity (gradient_opacity.cl) for each lane of a packet.
#ifndef VOXRAY_GRADIENT_OPACITY_LANES_CL
#define VOXRAY_GRADIENT_OPACITY_LANES_CL

#include "classification/gradient_opacity.cl"
#include "reconstruction/sampling_lanes.cl"
#include "shading/shading_lanes.cl"

// Compiled only where used; the includes above are expanded regardless of #if
// (engine/src/kernel_source.cpp), so they stay outside.
#if GRADIENT_OPACITY
inline floatN gradient_opacityN(__global const float4* lut, __constant RaycastParams* P, VecN g_w) {
  __global const float* table = (__global const float*)(lut + P->dims.w);
  float last = P->gradient_opacity.y;
  floatN x = fmin(sqrt(dotN(g_w, g_w)) * P->gradient_opacity.x, last);
  floatN x0 = floor(x);
  intN k = convert_intN(x0);
  intN k1 = min(k + 1, (intN)((int)last));
  return mix(gather_floatN(table, k), gather_floatN(table, k1), x - x0);
}

#endif  // GRADIENT_OPACITY

#endif
