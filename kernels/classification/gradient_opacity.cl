// GRADIENT_OPACITY (switches.h): dvr opacity times a factor of the gradient magnitude (issue 35,
// VTK's and Slicer's gradient opacity), so that homogeneous regions can fade while boundaries
// show. The factors (gradient_table.h) ride in the table buffer behind the colour table's
// P->dims.w entries: P->gradient_opacity.y + 1 of them over |gradient| in stored units per mm,
// P->gradient_opacity.x entries per unit, linear between, the last beyond.
// engine/src/transfer_function.cpp (GradientTable) bakes and reads the same table.
#ifndef VOXRAY_GRADIENT_OPACITY_CL
#define VOXRAY_GRADIENT_OPACITY_CL

#include "gradient_table.h"
#include "params.cl"

// The factor at world gradient g_w (stored units per mm, world_gradient of march.cl).
// Compiled only where used; the includes above are expanded regardless of #if
// (engine/src/kernel_source.cpp), so they stay outside.
#if GRADIENT_OPACITY
inline float gradient_opacity(__global const float4* lut, __constant RaycastParams* P, float3 g_w) {
  __global const float* table = (__global const float*)(lut + P->dims.w);
  float last = P->gradient_opacity.y;
  float x = fmin(length(g_w) * P->gradient_opacity.x, last);
  float i = floor(x);
  int k = (int)i;
  int k1 = min(k + 1, (int)last);
  return mix(table[k], table[k1], x - i);
}

#endif  // GRADIENT_OPACITY

#endif
