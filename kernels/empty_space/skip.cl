// Empty-space skipping over a grid of macro cells of CELL^3 voxels. Cell c holds the
// samples at positions p with floor(p / CELL) == c (clamped into the grid); its min/max
// (engine/src/macro_cells.cpp) covers voxels CELL*c - 1 ... CELL*(c + 1), which every
// trilinear or nearest sample of such a p reads, with a voxel to spare for rounding.
// classify.cl turns min/max into occupancy for the frame's iso range or transfer
// function (a sample in an empty cell cannot hit the iso range and has zero opacity, so
// leaping it changes no pixel), then into `leap`: each cell's chessboard distance to the
// nearest occupied cell. iso and dvr leap the whole empty cube around a cell at once;
// mip, whose emptiness depends on the running maximum, walks cell by cell with a 3D DDA
// and leaps cells whose max cannot raise it. Gradients are only taken at samples that are
// kept, so their wider footprint does not matter here.
#ifndef VOXRAY_SKIP_CL
#define VOXRAY_SKIP_CL

#include "intersection/ray.cl"
#include "variant.cl"

#define CELL_ARGS __global const uchar *leap, __global const short2 *range

inline int3 cell_of(__constant RaycastParams* P, float3 p) {
  return clamp(convert_int3(floor(p * (1.0f / CELL))), (int3)(0), P->cells.xyz - 1);
}

// The first index at or after sample (or segment) i whose sample may lie in an occupied
// cell (n + 1 when none), for iso and dvr; *check is the first index past that cell,
// where the caller asks again. From the cell at the current position it leaps to the exit
// of the empty cube of radius leap - 1 around it. Along an axis, the outermost cells
// reach to infinity: positions outside the grid are clamped into them, like the samples.
inline int ess_leap(CELL_ARGS, __constant RaycastParams* P, const Ray* r, bool segments, int i,
                    int* check) {
  int3 last = P->cells.xyz - 1;
  int3 ahead = isgreater(r->d, 0.0f);
  float3 ad = fabs(r->d);
  // Each leap moves the position by at least a thousandth of a voxel and a few ulps of t.
  float nudge = 1e-3f / fmax(ad.x, fmax(ad.y, ad.z));
  // t_land: where the last leap landed (none yet: sample i itself is the first candidate).
  float t_land = -FLT_MAX, t = ray_t(r, i, segments);
  int guard = last.x + last.y + last.z + 16;
  for (int g = 0; g < guard; ++g) {
    int3 c = cell_of(P, r->o + t * r->d);
    int k = (c.z * P->cells.y + c.y) * P->cells.x + c.x;
    int radius = max((int)leap[k] - 1, 0);
    int3 lo = c - radius, hi = c + radius;
    float3 plane = select(convert_float3(lo), convert_float3(hi + 1), ahead) * (float)CELL;
    float3 t_plane = (plane - r->o) * r->inv_d;
    int3 open = select(lo <= 0, hi >= last, ahead) | isequal(r->d, 0.0f);
    t_plane = select(t_plane, (float3)(FLT_MAX), open);
    float t_exit = fmin(t_plane.x, fmin(t_plane.y, t_plane.z));
    if (leap[k] == 0) {
      int first = max(i, ray_index_at(r, t_land, segments));
      *check = max(first + 1, ray_index_at(r, t_exit, segments));
      return first;
    }
    if (t_exit >= r->t1) return r->n + 1;
    t_land = fmax(t_land, t_exit);
    t = fmax(t, t_land) + fmax(nudge, fabs(t_land) * 5e-7f);
  }
  // Not expected: sample on from where the leaps got to (correct, only slower).
  int first = max(i, ray_index_at(r, t_land, segments));
  *check = first + 1;
  return first;
}

// mip: starting at sample i, walks the cells along the ray with a 3D DDA
// (Amanatides-Woo) while their max cannot raise the running maximum vmax. Returns the first index
// (n + 1 when none) whose sample lies in an occupied cell, and in *check the first index past that
// cell, where the caller asks again. Along an axis, the outermost cells reach to infinity:
// positions half a voxel outside the grid are clamped into them, like the samples themselves.
inline int ess_next_mip(__global const short2* range, __constant RaycastParams* P, const Ray* r,
                        int i, float vmax, int* check) {
  const bool segments = false;
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
    if ((float)range[k].y > vmax) {
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
