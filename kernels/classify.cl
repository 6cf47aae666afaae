// Occupancy of the macro cells for one frame's iso range or transfer function, run only
// when those change (engine/src/empty_space.cpp). One work-item per cell; range holds
// each cell's min/max with its apron (skip.cl says why). Conservative on purpose: a cell
// that might matter is occupied; half a stored unit and one table entry of margin absorb
// float rounding of samples and table positions.
//   mode 0 (iso): occupied when [min, max] meets the iso range P->values.xy
//   mode 1 (dvr): occupied when a table entry the cell's values can interpolate from has
//                 opacity > 0; opaque_before[k] counts such entries below k
#include "params.cl"

__kernel void classify(__global const short2* range, __constant RaycastParams* P,
                       __global const int* opaque_before, int mode, int cells,
                       __global uchar* occ) {
  int k = get_global_id(0);
  if (k >= cells) return;
  float lo = range[k].x - 0.5f, hi = range[k].y + 0.5f;
  if (mode == 0) {
    occ[k] = hi >= P->values.x && lo <= P->values.y;
    return;
  }
  int last = P->dims.w - 1;
  float x0 = clamp((lo - P->values.z) * P->values.w, 0.0f, (float)last);
  float x1 = clamp((hi - P->values.z) * P->values.w, 0.0f, (float)last);
  int a = max((int)floor(x0) - 1, 0), b = min((int)floor(x1) + 2, last);
  occ[k] = opaque_before[b + 1] - opaque_before[a] > 0;
}
