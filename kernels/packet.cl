// iso, dvr and mip for CPUs: one work-item marches a packet of 4x2 neighbouring rays with
// float8 lanes. PoCL runs a per-ray loop as scalar code, one ray at a time; here the
// arithmetic of eight rays shares each vector instruction and only the volume loads stay
// scalar. The algorithms are march.cl's lane by lane: the same samples, the same
// empty-space leaps (skip.cl's ess_leap), the same bisection, so the image is the same.
// Lanes whose ray is done are masked; the packet runs until its last ray is.
// Volumes here are buffers (STORAGE_IMAGE 0) of fewer than 2^31 voxels (int indices).
#ifndef VOXRAY_PACKET_CL
#define VOXRAY_PACKET_CL

#include "gradients8.cl"
#include "march.cl"

// Eight rays, one per lane, in voxel coordinates (see Ray in ray.cl).
typedef struct {
  float8 ox, oy, oz, dx, dy, dz, ix, iy, iz;
  float8 t0, t1, j;
  int8 n;
} RayPacket;

// How many lanes of a mask are set.
inline int lanes8(int8 m) {
  int8 b = m & 1;
  int4 h = b.lo + b.hi;
  return h.x + h.y + h.z + h.w;
}

inline float8 sample_t8(const RayPacket* r, int8 i, float step) {
  return fmin(r->t0 + (convert_float8(i) + r->j) * step, r->t1);
}

// ray_index_at (ray.cl): the first sample (or, with `segments`, segment midpoint) index at
// or beyond t.
inline int8 index_at8(const RayPacket* r, float8 t, float step, bool segments) {
  float8 k = (t - r->t0) / step - r->j + (segments ? 0.5f : 0.0f);
  return convert_int8(clamp(ceil(k), 0.0f, convert_float8(r->n + 1)));
}

// ray_segment (ray.cl): segment i spans [*a, *b].
inline void segment8(const RayPacket* r, int8 i, float step, float8* a, float8* b) {
  float8 fi = convert_float8(i) + r->j;
  *a = fmax(r->t0, r->t0 + (fi - 1.0f) * step);
  *b = fmin(r->t1, r->t0 + fi * step);
}

// ray_t (ray.cl): where sample (or segment midpoint) i lies.
inline float8 ray_t8(const RayPacket* r, int8 i, float step, bool segments) {
  if (!segments) return sample_t8(r, i, step);
  float8 a, b;
  segment8(r, i, step, &a, &b);
  return 0.5f * (a + b);
}

// The first sample index past the voxel cell [floor(p), floor(p) + 1] that sample t lies
// in (trilinear reads the same eight voxels, clamped, everywhere in it).
inline int8 past_voxel_cell8(const RayPacket* r, float8 t, float step) {
  float8 x = r->ox + t * r->dx, y = r->oy + t * r->dy, z = r->oz + t * r->dz;
  float8 px = floor(x) + select((float8)(0.0f), (float8)(1.0f), r->dx > 0.0f);
  float8 py = floor(y) + select((float8)(0.0f), (float8)(1.0f), r->dy > 0.0f);
  float8 pz = floor(z) + select((float8)(0.0f), (float8)(1.0f), r->dz > 0.0f);
  float8 tx = select((px - r->ox) * r->ix, (float8)(FLT_MAX), r->dx == 0.0f);
  float8 ty = select((py - r->oy) * r->iy, (float8)(FLT_MAX), r->dy == 0.0f);
  float8 tz = select((pz - r->oz) * r->iz, (float8)(FLT_MAX), r->dz == 0.0f);
  return index_at8(r, fmin(tx, fmin(ty, tz)), step, false);
}

// The macro cell (cx, cy, cz) that the point at t lies in, clamped to the grid; returns
// its index (0 for lanes outside `pending`).
inline int8 cell8(__constant RaycastParams* P, const RayPacket* r, float8 t, int8 pending, int8* cx,
                  int8* cy, int8* cz) {
  int4 last = P->cells - 1;
  *cx = clamp(convert_int8(floor((r->ox + t * r->dx) * (1.0f / CELL))), 0, last.x);
  *cy = clamp(convert_int8(floor((r->oy + t * r->dy) * (1.0f / CELL))), 0, last.y);
  *cz = clamp(convert_int8(floor((r->oz + t * r->dz) * (1.0f / CELL))), 0, last.z);
  return select((int8)(0), (*cz * P->cells.y + *cy) * P->cells.x + *cx, pending);
}

// Where each lane's ray leaves the cube of cells within `radius` of (cx, cy, cz). Along an
// axis the outermost cells reach to infinity (positions off the grid are clamped into
// them), as does an axis the ray runs parallel to: FLT_MAX.
inline float8 cube_exit8(__constant RaycastParams* P, const RayPacket* r, int8 cx, int8 cy, int8 cz,
                         int8 radius) {
  int4 last = P->cells - 1;
  int8 ahead_x = r->dx > 0.0f, ahead_y = r->dy > 0.0f, ahead_z = r->dz > 0.0f;
  float8 px = convert_float8(select(cx - radius, cx + radius + 1, ahead_x));
  float8 py = convert_float8(select(cy - radius, cy + radius + 1, ahead_y));
  float8 pz = convert_float8(select(cz - radius, cz + radius + 1, ahead_z));
  int8 open_x = select(cx - radius <= 0, cx + radius >= last.x, ahead_x) | (r->dx == 0.0f);
  int8 open_y = select(cy - radius <= 0, cy + radius >= last.y, ahead_y) | (r->dy == 0.0f);
  int8 open_z = select(cz - radius <= 0, cz + radius >= last.z, ahead_z) | (r->dz == 0.0f);
  float8 tx = select((px * (float)CELL - r->ox) * r->ix, (float8)(FLT_MAX), open_x);
  float8 ty = select((py * (float)CELL - r->oy) * r->iy, (float8)(FLT_MAX), open_y);
  float8 tz = select((pz * (float)CELL - r->oz) * r->iz, (float8)(FLT_MAX), open_z);
  return fmin(tx, fmin(ty, tz));
}

// Each lane's macro cell k's max (mip).
inline float8 cell_max8(__global const short2* range, int8 k) {
  return convert_float8((short8)(range[k.s0].y, range[k.s1].y, range[k.s2].y, range[k.s3].y,
                                 range[k.s4].y, range[k.s5].y, range[k.s6].y, range[k.s7].y));
}

// ess_leap (skip.cl) for the lanes in `need`: returns their next index, sets their *check.
// mip also passes an occupied cell whose max cannot raise a lane's floor (its running
// maximum, or the window's low end), as ess_next_mip does.
inline int8 ess_leap8(CELL_ARGS, __constant RaycastParams* P, const RayPacket* r, int8 i, int8 need,
                      float step, bool segments, bool mip, float8 floor_v, int8* check) {
  int4 last = P->cells - 1;
  float8 nudge = 1e-3f / fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  float8 t_land = -FLT_MAX, t = ray_t8(r, i, step, segments);  // as in ess_leap
  int8 result = i, pending = need;
  int guard = last.x + last.y + last.z + 16;
  for (int g = 0; g < guard && any(pending); ++g) {
    int8 cx, cy, cz;
    int8 k = cell8(P, r, t, pending, &cx, &cy, &cz);
    int8 d = convert_int8((uchar8)(leap[k.s0], leap[k.s1], leap[k.s2], leap[k.s3], leap[k.s4],
                                   leap[k.s5], leap[k.s6], leap[k.s7]));
    float8 t_exit = cube_exit8(P, r, cx, cy, cz, max(d - 1, 0));
    int8 found = pending & (d == 0);
    if (mip) found &= cell_max8(range, k) > floor_v;
    int8 first = max(i, index_at8(r, t_land, step, segments));
    result = select(result, first, found);
    *check = select(*check, max(first + 1, index_at8(r, t_exit, step, segments)), found);
    int8 beyond = pending & ~found & (t_exit >= r->t1);
    result = select(result, r->n + 1, beyond);
    pending &= ~(found | beyond);
    t_land = select(t_land, fmax(t_land, t_exit), pending);
    t = fmax(t, t_land) + fmax(nudge, fabs(t_land) * 5e-7f);
  }
  // Not expected: sample on from where the leaps got to (correct, only slower).
  int8 first = max(i, index_at8(r, t_land, step, segments));
  result = select(result, first, pending);
  *check = select(*check, first + 1, pending);
  return result;
}

// The empty-space step of iso and dvr packets: once enough of the active lanes have left
// their occupied cell, ess_leap8 moves those on. Leaping is optional (sampling on is
// always right) and a call costs every lane, so it waits for `every_lane` of them or for
// at least half. Returns the lanes still active.
inline int8 leap_packet8(CELL_ARGS, __constant RaycastParams* P, const RayPacket* r, int8* i,
                         int8* check, int8 active, float step, bool segments, bool every_lane) {
  int8 need = active & (*i >= *check);
  int n = lanes8(need), all = lanes8(active);
  if (n == 0 || (every_lane ? n < all : 2 * n < all)) return active;
  *i = select(*i, ess_leap8(leap, range, P, r, *i, need, step, segments, false, 0.0f, check), need);
  return active & ~(need & (*i > r->n));
}

// pixel_ray (raycast.cl) for the 4x2 pixels at (4 gx, 2 gy), lane l at (l & 3, l >> 2);
// the same formulas. Returns each lane's entry axis, -2 where there is no ray (a miss or
// a pixel outside the image); such lanes get a ray of length zero at the origin.
// w gets the rays in world space (origin, unit direction) for shading.
inline int8 pixel_rays8(__constant RaycastParams* P, int gx, int gy, RayPacket* r, float8 w[6]) {
  int width = P->image.x, height = P->image.y;
  int8 lane = (int8)(0, 1, 2, 3, 4, 5, 6, 7);
  int8 px = 4 * gx + (lane & 3), py = 2 * gy + (lane >> 2);
  float8 sx = (2.0f * (convert_float8(px) + 0.5f) / width - 1.0f) * P->view.x * P->view.y;
  float8 sy = (1.0f - 2.0f * (convert_float8(py) + 0.5f) / height) * P->view.x;
  float8 inv_len = 1.0f;
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
    float8 ux = P->forward_w.x + P->right_w.x * sx + P->up_w.x * sy;
    float8 uy = P->forward_w.y + P->right_w.y * sx + P->up_w.y * sy;
    float8 uz = P->forward_w.z + P->right_w.z * sx + P->up_w.z * sy;
    inv_len = rsqrt(ux * ux + uy * uy + uz * uz);
    w[0] = P->eye_w.x, w[1] = P->eye_w.y, w[2] = P->eye_w.z;
    w[3] = ux * inv_len, w[4] = uy * inv_len, w[5] = uz * inv_len;
    r->ox = P->eye_v.x, r->oy = P->eye_v.y, r->oz = P->eye_v.z;
    r->dx = (P->forward_v.x + P->right_v.x * sx + P->up_v.x * sy) * inv_len;
    r->dy = (P->forward_v.y + P->right_v.y * sx + P->up_v.y * sy) * inv_len;
    r->dz = (P->forward_v.z + P->right_v.z * sx + P->up_v.z * sy) * inv_len;
  }
  // intersect_box (intersect.cl): slabs; a zero direction component misses or never bounds.
  float8 o[3] = {r->ox, r->oy, r->oz}, d[3] = {r->dx, r->dy, r->dz};
  float lo[3] = {P->clip_lo.x, P->clip_lo.y, P->clip_lo.z};
  float hi[3] = {P->clip_hi.x, P->clip_hi.y, P->clip_hi.z};
  float8 t0 = -INFINITY, t1 = INFINITY;
  int8 axis = -1, miss = (px >= width) | (py >= height);
  for (int a = 0; a < 3; ++a) {
    int8 flat = d[a] == 0.0f;
    miss |= flat & ((o[a] < lo[a]) | (o[a] > hi[a]));
    float8 inv = 1.0f / d[a];
    float8 ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
    float8 near = select(fmin(ta, tb), (float8)(-INFINITY), flat);
    float8 far = select(fmax(ta, tb), (float8)(INFINITY), flat);
    int8 later = near > t0;
    axis = select(axis, (int8)(a), later);
    t0 = select(t0, near, later);
    t1 = fmin(t1, far);
  }
  int8 behind = t0 < 0.0f;
  t0 = select(t0, (float8)(0.0f), behind);
  axis = select(axis, (int8)(-1), behind);
  miss |= ~(t1 >= t0);
  axis = select(axis, (int8)(-2), miss);
  r->t0 = select(t0, (float8)(0.0f), miss);
  r->t1 = select(t1, (float8)(0.0f), miss);
  r->ix = select(1.0f / r->dx, (float8)(0.0f), r->dx == 0.0f);
  r->iy = select(1.0f / r->dy, (float8)(0.0f), r->dy == 0.0f);
  r->iz = select(1.0f / r->dz, (float8)(0.0f), r->dz == 0.0f);
  r->j = 0.0f;
  if (JITTER) {  // jitter_fraction (ray.cl)
    uint8 h = as_uint8(px) * 73856093u ^ as_uint8(py) * 19349663u;
    h = (h ^ (h >> 13)) * 0x5bd1e995u;
    h ^= h >> 15;
    r->j = convert_float8(h & 0xffffffu) / 16777216.0f;
  }
  r->n = select(convert_int8(clamp(ceil((r->t1 - r->t0) / P->view.z), (float8)(0.0f), 16777216.0f)),
                (int8)(-1), miss);
  // A lane without a ray marches nothing, at the origin (its indices stay in range).
  r->ox = select(r->ox, (float8)(0.0f), miss), r->oy = select(r->oy, (float8)(0.0f), miss);
  r->oz = select(r->oz, (float8)(0.0f), miss);
  r->dx = select(r->dx, (float8)(0.0f), miss), r->dy = select(r->dy, (float8)(0.0f), miss);
  r->dz = select(r->dz, (float8)(0.0f), miss);
  return axis;
}

// Writes the packet's pixels that lie inside the image, and adds its samples to a counter.
inline void write_packet(__constant RaycastParams* P, __global uchar4* out, __global uint* count,
                         int gx, int gy, Vec8 color, int8 samples) {
  float cr[8], cg[8], cb[8];
  int counts[8];
  vstore8(color.x, 0, cr), vstore8(color.y, 0, cg), vstore8(color.z, 0, cb);
  vstore8(samples, 0, counts);
  uint total = 0;
  for (int l = 0; l < 8; ++l) {
    int px = 4 * gx + (l & 3), py = 2 * gy + (l >> 2);
    if (px >= P->image.x || py >= P->image.y) continue;
    out[py * P->image.x + px] = to_rgba8((float3)(cr[l], cg[l], cb[l]));
    total += counts[l];
  }
  if (COUNT_SAMPLES) atomic_add(&count[(gx ^ gy) & 63], total);
}

// lut_lookup (march.cl) for eight values, as four channels. Each lane mixes its two
// entries as a float4; the eight results are transposed in registers.
inline void lut8(__global const float4* lut, __constant RaycastParams* P, float8 v,
                 float8 rgba[4]) {
  int last = P->dims.w - 1;
  float8 x = clamp((v - P->values.z) * P->values.w, 0.0f, (float)last);
  float8 x0 = floor(x), f = x - x0;
  int8 k = convert_int8(x0), k1 = min(k + 1, last);
#define LUT8_LANE(l) mix(lut[k.s##l], lut[k1.s##l], f.s##l)
  float4 e0 = LUT8_LANE(0), e1 = LUT8_LANE(1), e2 = LUT8_LANE(2), e3 = LUT8_LANE(3);
  float4 e4 = LUT8_LANE(4), e5 = LUT8_LANE(5), e6 = LUT8_LANE(6), e7 = LUT8_LANE(7);
#undef LUT8_LANE
  rgba[0] = (float8)(e0.x, e1.x, e2.x, e3.x, e4.x, e5.x, e6.x, e7.x);
  rgba[1] = (float8)(e0.y, e1.y, e2.y, e3.y, e4.y, e5.y, e6.y, e7.y);
  rgba[2] = (float8)(e0.z, e1.z, e2.z, e3.z, e4.z, e5.z, e6.z, e7.z);
  rgba[3] = (float8)(e0.w, e1.w, e2.w, e3.w, e4.w, e5.w, e6.w, e7.w);
}

// One component of an iso hit's normal: the gradient's where it was taken, the clip
// face's axis at a cap, 0 otherwise.
inline float8 cap_or_gradient8(float8 g, int8 graded, int8 cap, int8 along) {
  float8 zero = 0.0f;
  return select(select(zero, g, graded), select(zero, (float8)(1.0f), along), cap);
}

inline void iso_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global const float4* lut, __global uchar4* out, CELL_ARGS,
                       __global uint* count, int gx, int gy) {
  float step = P->view.z;
  RayPacket r;
  float8 world[6];
  int8 axis = pixel_rays8(P, gx, gy, &r, world);

  float lo = P->values.x, hi = P->values.y;
  int8 i = 0, check = 0, hit = -1, samples = 0;
  float8 t_hit = 0.0f;
  int8 active = r.n >= 0;
  while (any(active)) {
    if (ESS) {
      active = leap_packet8(leap, range, P, &r, &i, &check, active, step, false, false);
      if (!any(active)) break;
    }
    float8 t = sample_t8(&r, i, step);
    float8 vlo, vhi;
    float8 v = sample8_range(vol, P, r.ox + t * r.dx, r.oy + t * r.dy, r.oz + t * r.dz, &vlo, &vhi);
    samples -= active;  // true is -1
    int8 in = active & (v >= lo) & (v <= hi);
    hit = select(hit, i, in);
    t_hit = select(t_hit, t, in);
    active &= ~in;
    // Trilinear: a voxel cell whose eight voxels all miss the iso range holds no hit, so
    // the samples left in it are skipped (the same first hit; the one before it, where
    // refinement starts, is outside the range either way).
    int8 cell_misses = active & ((vhi < lo) | (vlo > hi));
    if (INTERP != 0 && any(cell_misses) != 0)
      i = select(i + 1, max(i + 1, past_voxel_cell8(&r, t, step)), cell_misses);
    else
      i += 1;
    active &= i <= r.n;
  }
  int8 refine = hit > 0;
  if (REFINE_STEPS > 0 && any(refine)) {
    float8 a = sample_t8(&r, hit - 1, step), b = t_hit;
    for (int k = 0; k < REFINE_STEPS; ++k) {
      float8 m = 0.5f * (a + b);
      float8 v = sample8(vol, P, r.ox + m * r.dx, r.oy + m * r.dy, r.oz + m * r.dz);
      int8 in = (v >= lo) & (v <= hi);
      b = select(b, m, in);
      a = select(m, a, in);
    }
    t_hit = select(t_hit, 0.5f * (a + b), refine);
    samples += select((int8)(0), (int8)(REFINE_STEPS), refine);
  }
  float8 hx = r.ox + t_hit * r.dx, hy = r.oy + t_hit * r.dy, hz = r.oz + t_hit * r.dz;
  int8 has_hit = hit >= 0;
  Vec8 color = {P->background.x, P->background.y, P->background.z};
  if (any(has_hit)) {
    float8 c[4];
    lut8(lut, P, sample8(vol, P, hx, hy, hz), c);
    Vec8 surface = {c[0], c[1], c[2]};
    if (SHADING) {
      // The gradient where the ray hits the surface; a ray that starts inside the surface
      // at a clip face shades the cut as a flat cap facing along that face's axis.
      Vec8 at = {hx, hy, hz};
      Vec8 g = volume_gradient8(vol, P, at);
      int8 cap = (hit == 0) & (axis >= 0);
      int8 graded = (hit > 0) | ((hit == 0) & (axis < 0));
      Vec8 n = {cap_or_gradient8(g.x, graded, cap, axis == 0),
                cap_or_gradient8(g.y, graded, cap, axis == 1),
                cap_or_gradient8(g.z, graded, cap, axis == 2)};
      samples += select((int8)(0), (int8)(GRADIENT_TAPS), graded);
      Vec8 normal = gradient_to_world8(P, n);
      Vec8 pos = {world[0] + t_hit * world[3], world[1] + t_hit * world[4],
                  world[2] + t_hit * world[5]};
      Vec8 view = {-world[3], -world[4], -world[5]};
      surface = shade8(surface, normal, pos, view, P->light_w, P->light);
    }
    color.x = select(color.x, surface.x, has_hit);
    color.y = select(color.y, surface.y, has_hit);
    color.z = select(color.z, surface.z, has_hit);
  }
  write_packet(P, out, count, gx, gy, color, samples);
}

// march_dvr (march.cl) for a 4x2 packet: the same segments, leaps, opacity and early
// termination lane by lane. Gradients and shading run in SIMD when any lane's sample is
// seen (gradients8.cl).
inline void dvr_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global const float4* lut, __global uchar4* out, CELL_ARGS,
                       __global uint* count, int gx, int gy) {
  float step = P->view.z;
  RayPacket r;
  float8 world[6];
  pixel_rays8(P, gx, gy, &r, world);
  float8 acc[3] = {0.0f, 0.0f, 0.0f}, alpha = 0.0f;
  int8 i = 0, check = 0, samples = 0;
  int8 active = r.n >= 0;
  while (any(active)) {
    if (ESS) {
      // Waiting for every lane took 3 % less CPU time than iso's half (CThead, VTK's
      // transfer function, both orbits).
      active = leap_packet8(leap, range, P, &r, &i, &check, active, step, true, true);
      if (!any(active)) break;
    }
    float8 sa, sb;
    segment8(&r, i, step, &sa, &sb);
    float8 seg = sb - sa;
    int8 live = active & (seg > 0.0f);  // segment 0 without jitter is empty
    if (any(live)) {
      float8 t = 0.5f * (sa + sb);
      float8 x = r.ox + t * r.dx, y = r.oy + t * r.dy, z = r.oz + t * r.dz;
      float8 c[4];
      lut8(lut, P, sample8(vol, P, x, y, z), c);
      samples -= live;
      int8 seen = live & (c[3] > 0.0f);
      if (any(seen)) {
        float8 a = c[3];
        if (OPACITY_CORRECTION) {
          float8 ratio = seg / P->view.w;
          a = CORRECTED_OPACITY(a, ratio);
        }
        if (SHADING) {
          Vec8 at = {x, y, z};
          Vec8 normal = gradient_to_world8(P, volume_gradient8(vol, P, at));
          Vec8 color = {c[0], c[1], c[2]};
          Vec8 pos = {world[0] + t * world[3], world[1] + t * world[4], world[2] + t * world[5]};
          Vec8 view = {-world[3], -world[4], -world[5]};
          Vec8 lit = shade8(color, normal, pos, view, P->light_w, P->light);
          c[0] = lit.x, c[1] = lit.y, c[2] = lit.z;
          samples += select((int8)(0), (int8)(GRADIENT_TAPS), seen);
        }
        float8 w = select((float8)(0.0f), (1.0f - alpha) * a, seen);
        for (int ch = 0; ch < 3; ++ch) acc[ch] += w * c[ch];
        alpha += w;
        active &= ~(seen & (alpha >= P->dvr.z));
      }
    }
    i += 1;
    active &= i <= r.n;
  }
  Vec8 color = {acc[0] + (1.0f - alpha) * P->background.x,
                acc[1] + (1.0f - alpha) * P->background.y,
                acc[2] + (1.0f - alpha) * P->background.z};
  write_packet(P, out, count, gx, gy, color, samples);
}

// Steps of the cell walk a mip packet keeps (float8 x 3 each in private memory); a ray
// that crosses more cells takes the walk-as-you-go loop instead.
#define MIP_WALK 256

// Walks every lane's cells in order (a 3D DDA by exit planes, no samples) and keeps step
// g's cell in max[g], t_in[g], t_out[g], its max as -FLT_MAX where it cannot show above
// the window's low end. Returns the number of steps, or -1 when a ray needs more.
inline int walk_cells8(__global const short2* range, __constant RaycastParams* P,
                       const RayPacket* r, float low, float8* max, float8* t_in, float8* t_out) {
  float8 nudge = 1e-3f / fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  float8 t = r->t0, t_enter = r->t0;
  int8 pending = r->n >= 0;
  int g = 0;
  for (; any(pending); ++g) {
    if (g == MIP_WALK) return -1;
    int8 cx, cy, cz;
    int8 k = cell8(P, r, t, pending, &cx, &cy, &cz);
    float8 t_exit = fmin(cube_exit8(P, r, cx, cy, cz, 0), r->t1);
    float8 m = cell_max8(range, k);
    max[g] = select((float8)(-FLT_MAX), m, pending & (m > low));
    t_in[g] = t_enter;
    t_out[g] = t_exit;
    pending &= t_exit < r->t1;
    t_enter = select(t_enter, t_exit, pending);
    t = select(t, fmax(t, t_exit) + fmax(nudge, fabs(t_exit) * 5e-7f), pending);
  }
  return g;
}

// Lane l of v[g] for each lane's own step g = at.sl.
inline float8 pick8(const float8* v, int8 at) {
  const float* f = (const float*)v;
  return (float8)(f[at.s0 * 8], f[at.s1 * 8 + 1], f[at.s2 * 8 + 2], f[at.s3 * 8 + 3],
                  f[at.s4 * 8 + 4], f[at.s5 * 8 + 5], f[at.s6 * 8 + 6], f[at.s7 * 8 + 7]);
}

// Samples j ... end for the lanes in `todo`, raising *vmax until it reaches the window's
// high end; with trilinear, the rest of a voxel cell whose eight voxels cannot raise the
// lane's floor (its maximum, or the window's low end) is skipped.
inline void sample_span8(__global const short* restrict vol, __constant RaycastParams* P,
                         const RayPacket* r, int8 j, int8 end, int8 todo, float low, float high,
                         float8* vmax, int8* samples) {
  float step = P->view.z;
  todo &= j <= end;
  while (any(todo)) {
    float8 t = sample_t8(r, j, step);
    float8 vlo, vhi;
    float8 v =
        sample8_range(vol, P, r->ox + t * r->dx, r->oy + t * r->dy, r->oz + t * r->dz, &vlo, &vhi);
    *samples -= todo;
    *vmax = select(*vmax, fmax(*vmax, v), todo);
    todo &= *vmax < high;
    int8 cell_below = todo & (vhi <= fmax(*vmax, low));
    if (INTERP != 0 && any(cell_below) != 0)
      j = select(j + 1, max(j + 1, past_voxel_cell8(r, t, step)), cell_below);
    else
      j += 1;
    todo &= j <= end;
  }
}

// march_mip (march.cl) for a 4x2 packet. Only what can change the windowed grey is
// sampled: values at or below the window's low end show black, so the running maximum
// starts there for skipping; a lane stops once it reaches the window's high end (white);
// and with trilinear the rest of a voxel cell whose eight voxels cannot exceed the lane's
// floor is skipped. Each is exact: the grey of every pixel is unchanged.
inline void mip_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global uchar4* out, CELL_ARGS, __global uint* count, int gx, int gy) {
  float step = P->view.z;
  RayPacket r;
  float8 world[6];
  pixel_rays8(P, gx, gy, &r, world);
  float low = P->dvr.x, high = P->dvr.x + 1.0f / P->dvr.y;
  float8 vmax = -FLT_MAX;
  int8 i = 0, check = 0, samples = 0;
  int8 active = r.n >= 0;
  if (ESS) {
    // The maximum does not depend on the order of the samples: walk the cells once, then
    // sample them brightest first, until no cell left can raise a lane's maximum (or
    // show above the window's low end). Most rays sample a few cells.
    float8 cell_max[MIP_WALK], t_in[MIP_WALK], t_out[MIP_WALK];
    int steps = walk_cells8(range, P, &r, low, cell_max, t_in, t_out);
    if (steps >= 0) {
      while (any(active)) {
        float8 best = -FLT_MAX;
        int8 at = 0;
        for (int g = 0; g < steps; ++g) {
          int8 better = cell_max[g] > best;
          best = select(best, cell_max[g], better);
          at = select(at, (int8)(g), better);
        }
        active &= best > fmax(vmax, low);
        if (!any(active)) break;
        float* m = (float*)cell_max;  // taken: lane l of step at.sl
        m[at.s0 * 8] = m[at.s1 * 8 + 1] = m[at.s2 * 8 + 2] = m[at.s3 * 8 + 3] = -FLT_MAX;
        m[at.s4 * 8 + 4] = m[at.s5 * 8 + 5] = m[at.s6 * 8 + 6] = m[at.s7 * 8 + 7] = -FLT_MAX;
        // The samples with t in [t_in, t_out), up to the last one at t1. One that rounding
        // puts in the neighbouring cell is within a voxel of the face, and so within
        // that cell's max (its apron): leaving it to that cell is exact.
        float8 from = pick8(t_in, at), to = pick8(t_out, at);
        int8 end = select(index_at8(&r, to, step, false) - 1, r.n, to >= r.t1);
        sample_span8(vol, P, &r, index_at8(&r, from, step, false), end, active, low, high, &vmax,
                     &samples);
        active &= vmax < high;
      }
    }
  }
  // Without ESS, or for a ray that crosses more cells than the walk keeps: in order, a
  // span at a time between leaps past cells that cannot raise a lane's floor.
  while (any(active)) {
    int8 end = r.n;
    if (ESS) {
      float8 floor_v = fmax(vmax, low);
      i = select(i, ess_leap8(leap, range, P, &r, i, active, step, false, true, floor_v, &check),
                 active);
      active &= i <= r.n;
      if (!any(active)) break;
      end = min(check - 1, r.n);
    }
    sample_span8(vol, P, &r, i, end, active, low, high, &vmax, &samples);
    i = end + 1;
    active &= (i <= r.n) & (vmax < high);
  }
  float8 grey = clamp((vmax - low) * P->dvr.y, 0.0f, 1.0f);
  Vec8 color = {grey, grey, grey};
  write_packet(P, out, count, gx, gy, color, samples);
}

#endif
