// Where iso packets read their leaps: ess_leapN (skip_lanes.cl) at ahead_baseN's base. For
// each octant of ray directions, each cell's chessboard distance d to the nearest occupied
// cell ahead in that octant (kernels/classify.cl, leap_distance_ahead), stored behind the
// two-sided distances (engine/src/empty_space.cpp). A ray leaps the box of d cells ahead of
// its cell along each axis (cube_exitN with radius d - 1 already takes only the faces ahead),
// where the two-sided distance allows only the cube of radius d - 1 around it. Occupied
// cells are the same (d = 0), so the same samples are taken: exact.
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

#endif
