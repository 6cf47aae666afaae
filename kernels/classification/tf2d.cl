// TF2D (switches.h): dvr's colour and opacity from the 2D transfer function over (value,
// |gradient|) (issue 35; Kniss et al.). The table (tf2d_table.h) rides in the table buffer
// behind the colour table's P->dims.w entries: P->tf2d.x the stored value of column 0,
// P->tf2d.y columns per stored unit, P->tf2d.z rows per stored unit / mm of |gradient|;
// bilinear, clamped. engine/src/tf2d.cpp (Tf2dTable) bakes and reads the same table.
#ifndef VOXRAY_TF2D_CL
#define VOXRAY_TF2D_CL

#include "params.cl"
#include "tf2d_table.h"

// Compiled only where used; the includes above are expanded regardless of #if
// (engine/src/kernel_source.cpp), so they stay outside.
#if TF2D
// The table's entry at stored value v and world gradient g_w (stored units per mm, the one
// shading takes: world_gradient of march.cl).
inline float4 tf2d_lookup(__global const float4* lut, __constant RaycastParams* P, float v,
                          float3 g_w) {
  __global const float4* table = lut + P->dims.w;
  float x = clamp((v - P->tf2d.x) * P->tf2d.y, 0.0f, (float)(VOXRAY_TF2D_VALUES - 1));
  float y = fmin(length(g_w) * P->tf2d.z, (float)(VOXRAY_TF2D_GRADIENTS - 1));
  float x0 = floor(x), y0 = floor(y);
  int i = (int)x0, j = (int)y0;
  int i1 = min(i + 1, VOXRAY_TF2D_VALUES - 1), j1 = min(j + 1, VOXRAY_TF2D_GRADIENTS - 1);
  float fx = x - x0;
  float4 a = mix(table[j * VOXRAY_TF2D_VALUES + i], table[j * VOXRAY_TF2D_VALUES + i1], fx);
  float4 b = mix(table[j1 * VOXRAY_TF2D_VALUES + i], table[j1 * VOXRAY_TF2D_VALUES + i1], fx);
  return mix(a, b, y - y0);
}

#endif  // TF2D

#endif
