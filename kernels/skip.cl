// Empty-space skipping over a grid of macro cells of CELL^3 voxels. Cell c holds the
// samples at positions p with floor(p / CELL) == c (clamped into the grid); its min/max
// (engine/src/macro_cells.cpp) covers voxels CELL*c - 1 ... CELL*(c + 1), which every
// trilinear or nearest sample of such a p reads, with a voxel to spare for rounding.
// classify.cl turns min/max into occupancy for the frame's iso range or transfer
// function: a sample in an empty cell cannot hit the iso range and has zero opacity, so
// leaping it changes no pixel. Gradients are only taken at samples that are kept, so
// their wider footprint does not matter here. mip leaps cells whose max cannot raise the
// running maximum.
#ifndef VOXRAY_SKIP_CL
#define VOXRAY_SKIP_CL

#include "ray.cl"
#include "variant.cl"

#define CELL_ARGS __global const uchar *occ, __global const short2 *range

inline int3 cell_of(__constant RaycastParams* P, float3 p) {
  return clamp(convert_int3(floor(p * (1.0f / CELL))), (int3)(0), P->cells.xyz - 1);
}

// Is cell k empty for this frame? mip: its max cannot raise the running maximum vmax.
inline bool cell_empty(CELL_ARGS, __constant RaycastParams* P, int k, float vmax) {
  return MODE == 2 ? (float)range[k].y <= vmax : occ[k] == 0;
}

// Starting at sample (or segment) i, walks the cells along the ray with a 3D DDA
// (Amanatides-Woo) while they are empty. Returns the first index (n + 1 when none) whose
// sample lies in an occupied cell, and in *check the first index past that cell, where
// the caller asks again. Along an axis, the outermost cells reach to infinity: positions
// half a voxel outside the grid are clamped into them, like the samples themselves.
inline int ess_next(CELL_ARGS, __constant RaycastParams* P, const Ray* r, bool segments, int i,
                    float vmax, int* check) {
  int3 c = cell_of(P, r->o + ray_t(r, i, segments) * r->d);
  int3 last = P->cells.xyz - 1;
  int3 s = select((int3)(-1), (int3)(1), isgreater(r->d, 0.0f));
  float3 lo = convert_float3(c) * (float)CELL;
  float3 plane = select(lo, lo + (float)CELL, isgreater(r->d, 0.0f));
  float3 t_max = (plane - r->o) * r->inv_d;
  float3 t_delta = fabs(r->inv_d) * (float)CELL;
  int3 beyond = c + s < 0 || c + s > last || isequal(r->d, 0.0f);
  t_max = select(t_max, (float3)(FLT_MAX), beyond);
  int3 stride = (int3)(1, P->cells.x, P->cells.x * P->cells.y);
  int k = c.z * stride.z + c.y * stride.y + c.x;
  float t_enter = -FLT_MAX;
  for (;;) {
    float t_exit = fmin(t_max.x, fmin(t_max.y, t_max.z));
    if (!cell_empty(occ, range, P, k, vmax)) {
      int first = max(i, ray_index_at(r, t_enter, segments));
      *check = max(first + 1, ray_index_at(r, t_exit, segments));
      return first;
    }
    if (t_exit >= r->t1) return r->n + 1;
    t_enter = t_exit;
    // Step along the axis whose boundary comes first; an axis with no cell beyond is parked.
    if (t_max.x == t_exit) {
      c.x += s.x;
      k += s.x;
      t_max.x = c.x + s.x < 0 || c.x + s.x > last.x ? FLT_MAX : t_max.x + t_delta.x;
    } else if (t_max.y == t_exit) {
      c.y += s.y;
      k += s.y * stride.y;
      t_max.y = c.y + s.y < 0 || c.y + s.y > last.y ? FLT_MAX : t_max.y + t_delta.y;
    } else {
      c.z += s.z;
      k += s.z * stride.z;
      t_max.z = c.z + s.z < 0 || c.z + s.z > last.z ? FLT_MAX : t_max.z + t_delta.z;
    }
  }
}

#endif
