// Empty-space skipping for ray packets, the lane-by-lane twin of skip.cl: the same leaps
// over the same macro cells.
#ifndef VOXRAY_SKIP_LANES_CL
#define VOXRAY_SKIP_LANES_CL

#include "empty_space/skip.cl"
#include "intersection/ray_lanes.cl"

// The macro cell (cx, cy, cz) that the point at t lies in, clamped to the grid; returns
// its index (0 for lanes outside `pending`).
inline intN cellN(__constant RaycastParams* P, const RayPacket* r, floatN t, intN pending, intN* cx,
                  intN* cy, intN* cz) {
  int4 last = P->cells - 1;
  *cx = clamp(convert_intN(floor((r->ox + t * r->dx) * (1.0f / CELL))), 0, last.x);
  *cy = clamp(convert_intN(floor((r->oy + t * r->dy) * (1.0f / CELL))), 0, last.y);
  *cz = clamp(convert_intN(floor((r->oz + t * r->dz) * (1.0f / CELL))), 0, last.z);
  return select((intN)(0), (*cz * P->cells.y + *cy) * P->cells.x + *cx, pending);
}

// Where each lane's ray leaves the cube of cells within `radius` of (cx, cy, cz), and in
// *ex, *ey, *ez where it crosses each axis's exit plane. Along an axis the outermost cells
// reach to infinity (positions off the grid are clamped into them), as does an axis the
// ray runs parallel to: FLT_MAX.
inline floatN cube_exit_planesN(__constant RaycastParams* P, const RayPacket* r, intN cx, intN cy,
                                intN cz, intN radius, floatN* ex, floatN* ey, floatN* ez) {
  int4 last = P->cells - 1;
  intN ahead_x = r->dx > 0.0f, ahead_y = r->dy > 0.0f, ahead_z = r->dz > 0.0f;
  floatN px = convert_floatN(select(cx - radius, cx + radius + 1, ahead_x));
  floatN py = convert_floatN(select(cy - radius, cy + radius + 1, ahead_y));
  floatN pz = convert_floatN(select(cz - radius, cz + radius + 1, ahead_z));
  intN open_x = select(cx - radius <= 0, cx + radius >= last.x, ahead_x) | (r->dx == 0.0f);
  intN open_y = select(cy - radius <= 0, cy + radius >= last.y, ahead_y) | (r->dy == 0.0f);
  intN open_z = select(cz - radius <= 0, cz + radius >= last.z, ahead_z) | (r->dz == 0.0f);
  *ex = select((px * (float)CELL - r->ox) * r->ix, (floatN)(FLT_MAX), open_x);
  *ey = select((py * (float)CELL - r->oy) * r->iy, (floatN)(FLT_MAX), open_y);
  *ez = select((pz * (float)CELL - r->oz) * r->iz, (floatN)(FLT_MAX), open_z);
  return fmin(*ex, fmin(*ey, *ez));
}

inline floatN cube_exitN(__constant RaycastParams* P, const RayPacket* r, intN cx, intN cy, intN cz,
                         intN radius) {
  floatN ex, ey, ez;
  return cube_exit_planesN(P, r, cx, cy, cz, radius, &ex, &ey, &ez);
}

// Each lane's macro cell k's max (mip).
inline floatN cell_maxN(__global const short2* range, intN k) {
#define CELL_MAX_LANE(l, n) range[k.s##l].y
  return convert_floatN((shortN)(LANE_LIST(CELL_MAX_LANE)));
#undef CELL_MAX_LANE
}

// ess_leap (skip.cl) for the lanes in `need`: returns their next index, sets their *check.
// mip also passes an occupied cell whose max cannot raise a lane's floor (its running
// maximum, or the window's low end), as ess_next_mip does. Each lane reads its distances
// at `base` in leap: 0 for the two-sided ones, iso's one-sided region (skip_ahead_lanes.cl).
inline intN ess_leapN(CELL_ARGS, __constant RaycastParams* P, const RayPacket* r, intN base, intN i,
                      intN need, float step, bool segments, bool mip, floatN floor_v, intN* check) {
  int4 last = P->cells - 1;
  floatN nudge = 1e-3f / fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  floatN t_land = -FLT_MAX, t = ray_tN(r, i, step, segments);  // as in ess_leap
  intN result = i, pending = need;
  int guard = last.x + last.y + last.z + 16;
  for (int g = 0; g < guard && any(pending); ++g) {
    intN cx, cy, cz;
    intN k = cellN(P, r, t, pending, &cx, &cy, &cz), at = k + base;
#define LEAP_LANE(l, n) leap[at.s##l]
    intN d = convert_intN((ucharN)(LANE_LIST(LEAP_LANE)));
#undef LEAP_LANE
    floatN t_exit = cube_exitN(P, r, cx, cy, cz, max(d - 1, 0));
    intN found = pending & (d == 0);
    if (mip) found &= cell_maxN(range, k) > floor_v;
    intN first = max(i, index_atN(r, t_land, step, segments));
    result = select(result, first, found);
    *check = select(*check, max(first + 1, index_atN(r, t_exit, step, segments)), found);
    intN beyond = pending & ~found & (t_exit >= r->t1);
    result = select(result, r->n + 1, beyond);
    pending &= ~(found | beyond);
    t_land = select(t_land, fmax(t_land, t_exit), pending);
    t = fmax(t, t_land) + fmax(nudge, fabs(t_land) * 5e-7f);
  }
  // Not expected: sample on from where the leaps got to (correct, only slower).
  intN first = max(i, index_atN(r, t_land, step, segments));
  result = select(result, first, pending);
  *check = select(*check, first + 1, pending);
  return result;
}

// The empty-space step of iso and dvr packets: once enough of the active lanes have left
// their occupied cell, ess_leapN moves those on. Leaping is optional (sampling on is
// always right) and a call costs every lane, so it waits for `every_lane` of them or for
// at least half. Returns the lanes still active.
inline intN leap_packetN(CELL_ARGS, __constant RaycastParams* P, const RayPacket* r, intN base,
                         intN* i, intN* check, intN active, float step, bool segments,
                         bool every_lane) {
  intN need = active & (*i >= *check);
  int n = count_lanes(need), all = count_lanes(active);
  if (n == 0 || (every_lane ? n < all : 2 * n < all)) return active;
  *i = select(*i, ess_leapN(leap, range, P, r, base, *i, need, step, segments, false, 0.0f, check),
              need);
  return active & ~(need & (*i > r->n));
}

#endif
