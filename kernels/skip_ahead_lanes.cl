// Empty-space leaps of iso packets over one-sided distances: for each octant of ray
// directions, each cell's chessboard distance d to the nearest occupied cell ahead in that
// octant (kernels/classify.cl, leap_distance_ahead), stored behind the two-sided distances
// (engine/src/empty_space.cpp). A ray leaps the box of d cells ahead of its cell along
// each axis (cube_exitN with radius d - 1 already takes only the faces ahead), where the
// two-sided distance allows only the cube of radius d - 1 around it. Occupied cells are the
// same (d = 0), so the same samples are taken: exact, like ess_leapN.
#ifndef VOXRAY_SKIP_AHEAD_LANES_CL
#define VOXRAY_SKIP_AHEAD_LANES_CL

#include "skip_lanes.cl"

// Each lane's region of the one-sided distances: octant bit a set where the direction
// along axis a is > 0 (cube_exitN's `ahead`).
inline intN ahead_baseN(__constant RaycastParams* P, const RayPacket* r) {
  int cells = P->cells.x * P->cells.y * P->cells.z;
  intN octant = ((r->dx > 0.0f) & 1) | ((r->dy > 0.0f) & 2) | ((r->dz > 0.0f) & 4);
  return (1 + octant) * cells;
}

// ess_leapN for iso (samples, no mip) over the one-sided distances at `base`.
inline intN ess_leap_aheadN(__global const uchar* leap, __constant RaycastParams* P,
                            const RayPacket* r, intN base, intN i, intN need, float step,
                            intN* check) {
  int4 last = P->cells - 1;
  floatN nudge = 1e-3f / fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  floatN t_land = -FLT_MAX, t = sample_tN(r, i, step);
  intN result = i, pending = need;
  int guard = last.x + last.y + last.z + 16;
  for (int g = 0; g < guard && any(pending); ++g) {
    intN cx, cy, cz;
    intN k = cellN(P, r, t, pending, &cx, &cy, &cz) + base;
#define LEAP_LANE(l, n) leap[k.s##l]
    intN d = convert_intN((ucharN)(LANE_LIST(LEAP_LANE)));
#undef LEAP_LANE
    floatN t_exit = cube_exitN(P, r, cx, cy, cz, max(d - 1, 0));
    intN found = pending & (d == 0);
    intN first = max(i, index_atN(r, t_land, step, false));
    result = select(result, first, found);
    *check = select(*check, max(first + 1, index_atN(r, t_exit, step, false)), found);
    intN beyond = pending & ~found & (t_exit >= r->t1);
    result = select(result, r->n + 1, beyond);
    pending &= ~(found | beyond);
    t_land = select(t_land, fmax(t_land, t_exit), pending);
    t = fmax(t, t_land) + fmax(nudge, fabs(t_land) * 5e-7f);
  }
  // Not expected: sample on from where the leaps got to (correct, only slower).
  intN first = max(i, index_atN(r, t_land, step, false));
  result = select(result, first, pending);
  *check = select(*check, first + 1, pending);
  return result;
}

// leap_packetN (skip_lanes.cl) for iso over the one-sided distances: leaps once at least
// half of the active lanes have left their occupied cell. Returns the lanes still active.
inline intN leap_packet_aheadN(__global const uchar* leap, __constant RaycastParams* P,
                               const RayPacket* r, intN base, intN* i, intN* check, intN active,
                               float step) {
  intN need = active & (*i >= *check);
  int n = count_lanes(need), all = count_lanes(active);
  if (n == 0 || 2 * n < all) return active;
  *i = select(*i, ess_leap_aheadN(leap, P, r, base, *i, need, step, check), need);
  return active & ~(need & (*i > r->n));
}

#endif
