// PREINT (switches.h): dvr's colour and opacity of a segment from the pre-integrated table
// (preint_table.h; Engel, Kraus, Ertl 2001) at (front value, back value): the segment's value
// is taken to run linearly from the previous sample's to this sample's, and the table holds the
// transfer function integrated along that run for the frame's step, so a long step no longer
// misses what the table shows between two samples. The table rides behind the colour table's
// P->dims.w entries: P->preint.x the stored value of row and column 0, P->preint.y entries per
// stored unit; bilinear, clamped. engine/src/preint_table.cpp (PreintTable) bakes and reads the
// same table.
#ifndef VOXRAY_PREINT_CL
#define VOXRAY_PREINT_CL

#include "params.cl"
#include "preint_table.h"

// Compiled only where used; the includes above are expanded regardless of #if
// (engine/src/kernel_source.cpp), so they stay outside.
#if PREINT
// The segment's colour (rgb) and opacity (w) from front value vf to back value vb; `ratio` its
// length over the frame's step (1 but for a ray's first and last segments). The table spans
// only the values where the transfer function shows (and a margin where it does not): a value
// beyond it is clamped, and the optical depth, a mean over the values the segment runs
// through, is scaled by the part of the run inside the table (the rest adds nothing).
inline float4 preint_lookup(__global const float4* lut, __constant RaycastParams* P, float vf,
                            float vb, float ratio) {
  __global const float4* table = lut + P->dims.w;
  const float last = (float)(VOXRAY_PREINT_VALUES - 1);
  float xf = (vf - P->preint.x) * P->preint.y, xb = (vb - P->preint.x) * P->preint.y;
  float cf = clamp(xf, 0.0f, last), cb = clamp(xb, 0.0f, last);
  float f0 = floor(cf), b0 = floor(cb);
  int i = (int)f0, j = (int)b0;
  int i1 = min(i + 1, VOXRAY_PREINT_VALUES - 1), j1 = min(j + 1, VOXRAY_PREINT_VALUES - 1);
  float fx = cb - b0;
  float4 a = mix(table[i * VOXRAY_PREINT_VALUES + j], table[i * VOXRAY_PREINT_VALUES + j1], fx);
  float4 b = mix(table[i1 * VOXRAY_PREINT_VALUES + j], table[i1 * VOXRAY_PREINT_VALUES + j1], fx);
  float4 e = mix(a, b, cf - f0);
  float run = fabs(xb - xf);
  float inside = run > 0.0f ? fabs(cb - cf) / run : 1.0f;
  e.w = 1.0f - native_exp2(-e.w * inside * ratio);
  return e;
}

#endif  // PREINT

#endif
