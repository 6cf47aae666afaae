// Where iso packets read their leaps: ess_leapN (skip_lanes.cl) at ahead_baseN's base. For
// each octant of ray directions, each cell's chessboard distance d to the nearest occupied
// cell ahead in that octant (classify.cl, leap_distance_ahead), stored behind the
// two-sided distances (engine/src/empty_space.cpp). A ray leaps the box of d cells ahead of
// its cell along each axis (cube_exitN with radius d - 1 already takes only the faces ahead),
// where the two-sided distance allows only the cube of radius d - 1 around it. Occupied
// cells are the same (d = 0), so the same samples are taken: exact.
#ifndef VOXRAY_SKIP_AHEAD_LANES_CL
#define VOXRAY_SKIP_AHEAD_LANES_CL

#include "empty_space/skip_lanes.cl"

// Each lane's region of the one-sided distances: octant bit a set where the direction
// along axis a is > 0 (cube_exitN's `ahead`).
inline intN ahead_baseN(__constant RaycastParams* P, const RayPacket* r) {
  int cells = P->cells.x * P->cells.y * P->cells.z;
  intN octant = ((r->dx > 0.0f) & 1) | ((r->dy > 0.0f) & 2) | ((r->dz > 0.0f) & 4);
  return (1 + octant) * cells;
}

// The iso block bits (engine/src/empty_space.cpp, isoBlocks), behind the one-sided
// distances: per macro cell, bit (bx & 1) | (by & 1) << 1 | (bz & 1) << 2 of the 2^3 voxel
// block (bx, by, bz) = floor(p / 2) (clamped into the grid) is set when a sample there can
// hit the iso range. Returns the lanes in `live` whose point p lies in a block without.
inline intN iso_block_emptyN(__global const uchar* leap, __constant RaycastParams* P, floatN x,
                             floatN y, floatN z, intN live) {
  int4 n = P->cells, last = 2 * n - 1;
  intN bx = clamp(convert_intN(floor(x * 0.5f)), 0, last.x);
  intN by = clamp(convert_intN(floor(y * 0.5f)), 0, last.y);
  intN bz = clamp(convert_intN(floor(z * 0.5f)), 0, last.z);
  intN k = select((intN)(0), ((bz >> 1) * n.y + (by >> 1)) * n.x + (bx >> 1), live);
  __global const uchar* bits = leap + 9 * n.x * n.y * n.z;
#define BLOCK_LANE(l, n) bits[k.s##l]
  intN b = convert_intN((ucharN)(LANE_LIST(BLOCK_LANE)));
#undef BLOCK_LANE
  intN bit = (bx & 1) | ((by & 1) << 1) | ((bz & 1) << 2);
  return live & (((b >> bit) & 1) == 0);
}

#endif
