// Ray packets for CPUs: LANES rays (lanes.cl), one per lane, the lane-by-lane twin of
// ray.cl: the same sample positions, segments and indices, and pixel_ray's rays.
#ifndef VOXRAY_RAY_LANES_CL
#define VOXRAY_RAY_LANES_CL

#include "intersection/ray.cl"
#include "jitter_hash.h"
#include "simd/lanes.cl"
#include "variant.cl"

// LANES rays (lanes.cl), one per lane, in voxel coordinates (see Ray in ray.cl).
typedef struct {
  floatN ox, oy, oz, dx, dy, dz, ix, iy, iz;
  floatN t0, t1, j;
  intN n;
} RayPacket;

inline floatN sample_tN(const RayPacket* r, intN i, float step) {
  return fmin(r->t0 + (convert_floatN(i) + r->j) * step, r->t1);
}

// ray_index_at (ray.cl): the first sample (or, with `segments`, segment midpoint) index at
// or beyond t.
inline intN index_atN(const RayPacket* r, floatN t, float step, bool segments) {
  floatN k = (t - r->t0) / step - r->j + (segments ? 0.5f : 0.0f);
  return convert_intN(clamp(ceil(k), 0.0f, convert_floatN(r->n + 1)));
}

// ray_segment (ray.cl): segment i spans [*a, *b].
inline void segmentN(const RayPacket* r, intN i, float step, floatN* a, floatN* b) {
  floatN fi = convert_floatN(i) + r->j;
  *a = fmax(r->t0, r->t0 + (fi - 1.0f) * step);
  *b = fmin(r->t1, r->t0 + fi * step);
}

// ray_t (ray.cl): where sample (or segment midpoint) i lies.
inline floatN ray_tN(const RayPacket* r, intN i, float step, bool segments) {
  if (!segments) return sample_tN(r, i, step);
  floatN a, b;
  segmentN(r, i, step, &a, &b);
  return 0.5f * (a + b);
}

// The first sample index past the cube [size floor(p / size), + size] that the point
// (x, y, z) lies in: a voxel cell (size 1) or a block of them.
inline intN past_cubeN(const RayPacket* r, floatN x, floatN y, floatN z, float size, float step) {
  float inv = 1.0f / size;
  floatN px = size * (floor(x * inv) + select((floatN)(0.0f), (floatN)(1.0f), r->dx > 0.0f));
  floatN py = size * (floor(y * inv) + select((floatN)(0.0f), (floatN)(1.0f), r->dy > 0.0f));
  floatN pz = size * (floor(z * inv) + select((floatN)(0.0f), (floatN)(1.0f), r->dz > 0.0f));
  floatN tx = select((px - r->ox) * r->ix, (floatN)(FLT_MAX), r->dx == 0.0f);
  floatN ty = select((py - r->oy) * r->iy, (floatN)(FLT_MAX), r->dy == 0.0f);
  floatN tz = select((pz - r->oz) * r->iz, (floatN)(FLT_MAX), r->dz == 0.0f);
  return index_atN(r, fmin(tx, fmin(ty, tz)), step, false);
}

// The first sample index past the voxel cell [floor(p), floor(p) + 1] that sample t lies
// in (trilinear reads the same eight voxels, clamped, everywhere in it).
inline intN past_voxel_cellN(const RayPacket* r, floatN t, float step) {
  return past_cubeN(r, r->ox + t * r->dx, r->oy + t * r->dy, r->oz + t * r->dz, 1.0f, step);
}

// pixel_ray (raycast.cl) for the 4 x PACKET_ROWS pixels at (4 gx, PACKET_ROWS gy), lane l at (l &
// 3, l >> 2); the same formulas. Returns each lane's entry axis, -2 where there is no ray (a miss
// or a pixel outside the image); such lanes get a ray of length zero at the origin. w gets the rays
// in world space (origin, unit direction) for shading.
inline intN pixel_raysN(__constant RaycastParams* P, int gx, int gy, RayPacket* r, floatN w[6]) {
  int width = P->image.x, height = P->image.y;
#define LANE_INDEX(l, n) n
  intN lane = (intN)(LANE_LIST(LANE_INDEX));
#undef LANE_INDEX
  intN px = 4 * gx + (lane & 3), py = PACKET_ROWS * gy + (lane >> 2);
  IMAGE_PASS_PIXEL(intN, px, py);  // the lattice pass: lanes on lattice pixels
  floatN sx = (2.0f * (convert_floatN(px) + 0.5f) / width - 1.0f) * P->view.x * P->view.y;
  floatN sy = (1.0f - 2.0f * (convert_floatN(py) + 0.5f) / height) * P->view.x;
  floatN inv_len = 1.0f;
  if (ORTHO) {
    w[0] = P->eye_w.x + P->right_w.x * sx + P->up_w.x * sy;
    w[1] = P->eye_w.y + P->right_w.y * sx + P->up_w.y * sy;
    w[2] = P->eye_w.z + P->right_w.z * sx + P->up_w.z * sy;
    w[3] = P->forward_w.x, w[4] = P->forward_w.y, w[5] = P->forward_w.z;
    r->ox = P->eye_v.x + P->right_v.x * sx + P->up_v.x * sy;
    r->oy = P->eye_v.y + P->right_v.y * sx + P->up_v.y * sy;
    r->oz = P->eye_v.z + P->right_v.z * sx + P->up_v.z * sy;
    r->dx = P->forward_v.x, r->dy = P->forward_v.y, r->dz = P->forward_v.z;
  } else {
    floatN ux = P->forward_w.x + P->right_w.x * sx + P->up_w.x * sy;
    floatN uy = P->forward_w.y + P->right_w.y * sx + P->up_w.y * sy;
    floatN uz = P->forward_w.z + P->right_w.z * sx + P->up_w.z * sy;
    inv_len = rsqrt(ux * ux + uy * uy + uz * uz);
    w[0] = P->eye_w.x, w[1] = P->eye_w.y, w[2] = P->eye_w.z;
    w[3] = ux * inv_len, w[4] = uy * inv_len, w[5] = uz * inv_len;
    r->ox = P->eye_v.x, r->oy = P->eye_v.y, r->oz = P->eye_v.z;
    r->dx = (P->forward_v.x + P->right_v.x * sx + P->up_v.x * sy) * inv_len;
    r->dy = (P->forward_v.y + P->right_v.y * sx + P->up_v.y * sy) * inv_len;
    r->dz = (P->forward_v.z + P->right_v.z * sx + P->up_v.z * sy) * inv_len;
  }
  // intersect_box (intersect.cl): slabs; a zero direction component misses or never bounds.
  floatN o[3] = {r->ox, r->oy, r->oz}, d[3] = {r->dx, r->dy, r->dz};
  float lo[3] = {P->clip_lo.x, P->clip_lo.y, P->clip_lo.z};
  float hi[3] = {P->clip_hi.x, P->clip_hi.y, P->clip_hi.z};
  floatN t0 = -INFINITY, t1 = INFINITY;
  intN axis = -1, miss = (px >= width) | (py >= height);
  for (int a = 0; a < 3; ++a) {
    intN flat = d[a] == 0.0f;
    float margin = 1e-5f * (1.0f + fabs(lo[a]) + fabs(hi[a]));  // as intersect_box's
    miss |= flat & ((o[a] < lo[a] - margin) | (o[a] > hi[a] + margin));
    floatN inv = 1.0f / d[a];
    floatN ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
    floatN near = select(fmin(ta, tb), (floatN)(-INFINITY), flat);
    floatN far = select(fmax(ta, tb), (floatN)(INFINITY), flat);
    intN later = near > t0;
    axis = select(axis, (intN)(a), later);
    t0 = select(t0, near, later);
    t1 = fmin(t1, far);
  }
  intN behind = t0 < 0.0f;
  t0 = select(t0, (floatN)(0.0f), behind);
  axis = select(axis, (intN)(-1), behind);
  miss |= ~(t1 >= t0);
  axis = select(axis, (intN)(-2), miss);
  r->t0 = select(t0, (floatN)(0.0f), miss);
  r->t1 = select(t1, (floatN)(0.0f), miss);
  r->ix = select(1.0f / r->dx, (floatN)(0.0f), r->dx == 0.0f);
  r->iy = select(1.0f / r->dy, (floatN)(0.0f), r->dy == 0.0f);
  r->iz = select(1.0f / r->dz, (floatN)(0.0f), r->dz == 0.0f);
  r->j = 0.0f;
  if (JITTER)  // jitter_fraction (ray.cl)
    r->j = convert_floatN(VOXRAY_JITTER_HASH(as_uintN(px), as_uintN(py))) / VOXRAY_JITTER_RANGE;
  r->n = select(convert_intN(clamp(ceil((r->t1 - r->t0) / P->view.z), (floatN)(0.0f), 16777216.0f)),
                (intN)(-1), miss);
  // A lane without a ray marches nothing, at the origin (its indices stay in range).
  r->ox = select(r->ox, (floatN)(0.0f), miss), r->oy = select(r->oy, (floatN)(0.0f), miss);
  r->oz = select(r->oz, (floatN)(0.0f), miss);
  r->dx = select(r->dx, (floatN)(0.0f), miss), r->dy = select(r->dy, (floatN)(0.0f), miss);
  r->dz = select(r->dz, (floatN)(0.0f), miss);
  return axis;
}

#endif
