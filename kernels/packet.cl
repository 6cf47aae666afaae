// iso, dvr and mip for CPUs: one work-item marches a packet of 4 x PACKET_ROWS neighbouring
// rays in floatN lanes (lanes.cl). PoCL runs a per-ray loop as scalar code, one ray at a
// time; here the arithmetic of LANES rays shares each vector instruction and only the volume loads
// stay scalar. The algorithms are march.cl's lane by lane: the same samples, the same empty-space
// leaps (skip.cl's ess_leap), the same bisection, so the image is the same. Lanes whose ray is done
// are masked; the packet runs until its last ray is. Volumes here are buffers (STORAGE_IMAGE 0) of
// fewer than 2^31 voxels (int indices).
#ifndef VOXRAY_PACKET_CL
#define VOXRAY_PACKET_CL

#include "gradients_lanes.cl"
#include "march.cl"

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

// The first sample index past the voxel cell [floor(p), floor(p) + 1] that sample t lies
// in (trilinear reads the same eight voxels, clamped, everywhere in it).
inline intN past_voxel_cellN(const RayPacket* r, floatN t, float step) {
  floatN x = r->ox + t * r->dx, y = r->oy + t * r->dy, z = r->oz + t * r->dz;
  floatN px = floor(x) + select((floatN)(0.0f), (floatN)(1.0f), r->dx > 0.0f);
  floatN py = floor(y) + select((floatN)(0.0f), (floatN)(1.0f), r->dy > 0.0f);
  floatN pz = floor(z) + select((floatN)(0.0f), (floatN)(1.0f), r->dz > 0.0f);
  floatN tx = select((px - r->ox) * r->ix, (floatN)(FLT_MAX), r->dx == 0.0f);
  floatN ty = select((py - r->oy) * r->iy, (floatN)(FLT_MAX), r->dy == 0.0f);
  floatN tz = select((pz - r->oz) * r->iz, (floatN)(FLT_MAX), r->dz == 0.0f);
  return index_atN(r, fmin(tx, fmin(ty, tz)), step, false);
}

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

// Where each lane's ray leaves the cube of cells within `radius` of (cx, cy, cz). Along an
// axis the outermost cells reach to infinity (positions off the grid are clamped into
// them), as does an axis the ray runs parallel to: FLT_MAX.
inline floatN cube_exitN(__constant RaycastParams* P, const RayPacket* r, intN cx, intN cy, intN cz,
                         intN radius) {
  int4 last = P->cells - 1;
  intN ahead_x = r->dx > 0.0f, ahead_y = r->dy > 0.0f, ahead_z = r->dz > 0.0f;
  floatN px = convert_floatN(select(cx - radius, cx + radius + 1, ahead_x));
  floatN py = convert_floatN(select(cy - radius, cy + radius + 1, ahead_y));
  floatN pz = convert_floatN(select(cz - radius, cz + radius + 1, ahead_z));
  intN open_x = select(cx - radius <= 0, cx + radius >= last.x, ahead_x) | (r->dx == 0.0f);
  intN open_y = select(cy - radius <= 0, cy + radius >= last.y, ahead_y) | (r->dy == 0.0f);
  intN open_z = select(cz - radius <= 0, cz + radius >= last.z, ahead_z) | (r->dz == 0.0f);
  floatN tx = select((px * (float)CELL - r->ox) * r->ix, (floatN)(FLT_MAX), open_x);
  floatN ty = select((py * (float)CELL - r->oy) * r->iy, (floatN)(FLT_MAX), open_y);
  floatN tz = select((pz * (float)CELL - r->oz) * r->iz, (floatN)(FLT_MAX), open_z);
  return fmin(tx, fmin(ty, tz));
}

// Each lane's macro cell k's max (mip).
inline floatN cell_maxN(__global const short2* range, intN k) {
#define CELL_MAX_LANE(l, n) range[k.s##l].y
  return convert_floatN((shortN)(LANE_LIST(CELL_MAX_LANE)));
#undef CELL_MAX_LANE
}

// ess_leap (skip.cl) for the lanes in `need`: returns their next index, sets their *check.
// mip also passes an occupied cell whose max cannot raise a lane's floor (its running
// maximum, or the window's low end), as ess_next_mip does.
inline intN ess_leapN(CELL_ARGS, __constant RaycastParams* P, const RayPacket* r, intN i, intN need,
                      float step, bool segments, bool mip, floatN floor_v, intN* check) {
  int4 last = P->cells - 1;
  floatN nudge = 1e-3f / fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  floatN t_land = -FLT_MAX, t = ray_tN(r, i, step, segments);  // as in ess_leap
  intN result = i, pending = need;
  int guard = last.x + last.y + last.z + 16;
  for (int g = 0; g < guard && any(pending); ++g) {
    intN cx, cy, cz;
    intN k = cellN(P, r, t, pending, &cx, &cy, &cz);
#define LEAP_LANE(l, n) leap[k.s##l]
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
inline intN leap_packetN(CELL_ARGS, __constant RaycastParams* P, const RayPacket* r, intN* i,
                         intN* check, intN active, float step, bool segments, bool every_lane) {
  intN need = active & (*i >= *check);
  int n = count_lanes(need), all = count_lanes(active);
  if (n == 0 || (every_lane ? n < all : 2 * n < all)) return active;
  *i = select(*i, ess_leapN(leap, range, P, r, *i, need, step, segments, false, 0.0f, check), need);
  return active & ~(need & (*i > r->n));
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
    miss |= flat & ((o[a] < lo[a]) | (o[a] > hi[a]));
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
  if (JITTER) {  // jitter_fraction (ray.cl)
    uintN h = as_uintN(px) * 73856093u ^ as_uintN(py) * 19349663u;
    h = (h ^ (h >> 13)) * 0x5bd1e995u;
    h ^= h >> 15;
    r->j = convert_floatN(h & 0xffffffu) / 16777216.0f;
  }
  r->n = select(convert_intN(clamp(ceil((r->t1 - r->t0) / P->view.z), (floatN)(0.0f), 16777216.0f)),
                (intN)(-1), miss);
  // A lane without a ray marches nothing, at the origin (its indices stay in range).
  r->ox = select(r->ox, (floatN)(0.0f), miss), r->oy = select(r->oy, (floatN)(0.0f), miss);
  r->oz = select(r->oz, (floatN)(0.0f), miss);
  r->dx = select(r->dx, (floatN)(0.0f), miss), r->dy = select(r->dy, (floatN)(0.0f), miss);
  r->dz = select(r->dz, (floatN)(0.0f), miss);
  return axis;
}

// Writes the packet's pixels that lie inside the image, and adds its samples to a counter.
inline void write_packet(__constant RaycastParams* P, __global uchar4* out, __global uint* count,
                         int gx, int gy, VecN color, intN samples) {
  float cr[LANES], cg[LANES], cb[LANES];
  int counts[LANES];
  vstoreN(color.x, 0, cr), vstoreN(color.y, 0, cg), vstoreN(color.z, 0, cb);
  vstoreN(samples, 0, counts);
  uint total = 0;
  for (int l = 0; l < LANES; ++l) {
    int px = 4 * gx + (l & 3), py = PACKET_ROWS * gy + (l >> 2);
    if (px >= P->image.x || py >= P->image.y) continue;
    out[py * P->image.x + px] = to_rgba8((float3)(cr[l], cg[l], cb[l]));
    total += counts[l];
  }
  if (COUNT_SAMPLES) atomic_add(&count[(gx ^ gy) & 63], total);
}

// Where each lane's value falls in the table (lut_lookup, march.cl): entries *k and *k1,
// mixed by *f.
inline void lut_spotN(__constant RaycastParams* P, floatN v, intN* k, intN* k1, floatN* f) {
  int last = P->dims.w - 1;
  floatN x = clamp((v - P->values.z) * P->values.w, 0.0f, (float)last);
  floatN x0 = floor(x);
  *f = x - x0;
  *k = convert_intN(x0);
  *k1 = min(*k + 1, last);
}

// Only the opacity: two gathers (dvr with shading looks the colour up when it shades).
inline floatN lut_alphaN(__global const float4* lut, __constant RaycastParams* P, floatN v) {
  intN k, k1;
  floatN f;
  lut_spotN(P, v, &k, &k1, &f);
  __global const float* alpha = (__global const float*)lut + 3;
  return mix(gather_floatN(alpha, 4 * k), gather_floatN(alpha, 4 * k1), f);
}

// lut_lookup for each lane's value, as four channels. Each lane mixes its two entries as a
// float4; the results are transposed in registers.
inline void lutN(__global const float4* lut, __constant RaycastParams* P, floatN v,
                 floatN rgba[4]) {
  intN k, k1;
  floatN f;
  lut_spotN(P, v, &k, &k1, &f);
  float4 e[LANES];
#define LUT_LANE(l, n) e[n] = mix(lut[k.s##l], lut[k1.s##l], f.s##l);
#define LUT_X(l, n) e[n].x
#define LUT_Y(l, n) e[n].y
#define LUT_Z(l, n) e[n].z
#define LUT_W(l, n) e[n].w
  LANE_EACH(LUT_LANE)
  rgba[0] = (floatN)(LANE_LIST(LUT_X));
  rgba[1] = (floatN)(LANE_LIST(LUT_Y));
  rgba[2] = (floatN)(LANE_LIST(LUT_Z));
  rgba[3] = (floatN)(LANE_LIST(LUT_W));
#undef LUT_LANE
#undef LUT_X
#undef LUT_Y
#undef LUT_Z
#undef LUT_W
}

// One component of an iso hit's normal: the gradient's where it was taken, the clip
// face's axis at a cap, 0 otherwise.
inline floatN cap_or_gradientN(floatN g, intN graded, intN cap, intN along) {
  floatN zero = 0.0f;
  return select(select(zero, g, graded), select(zero, (floatN)(1.0f), along), cap);
}

inline void iso_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global const float4* lut, __global uchar4* out, CELL_ARGS,
                       __global uint* count, int gx, int gy) {
  float step = P->view.z;
  RayPacket r;
  floatN world[6];
  intN axis = pixel_raysN(P, gx, gy, &r, world);

  float lo = P->values.x, hi = P->values.y;
  intN i = 0, check = 0, hit = -1, samples = 0;
  floatN t_hit = 0.0f;
  intN active = r.n >= 0;
  while (any(active)) {
    if (ESS) {
      active = leap_packetN(leap, range, P, &r, &i, &check, active, step, false, false);
      if (!any(active)) break;
    }
    floatN t = sample_tN(&r, i, step);
    floatN vlo, vhi;
    floatN v = sample_rangeN(vol, P, r.ox + t * r.dx, r.oy + t * r.dy, r.oz + t * r.dz, &vlo, &vhi);
    samples -= active;  // true is -1
    intN in = active & (v >= lo) & (v <= hi);
    hit = select(hit, i, in);
    t_hit = select(t_hit, t, in);
    active &= ~in;
    // Trilinear: a voxel cell whose eight voxels all miss the iso range holds no hit, so
    // the samples left in it are skipped (the same first hit; the one before it, where
    // refinement starts, is outside the range either way).
    intN cell_misses = active & ((vhi < lo) | (vlo > hi));
    if (INTERP != 0 && any(cell_misses) != 0)
      i = select(i + 1, max(i + 1, past_voxel_cellN(&r, t, step)), cell_misses);
    else
      i += 1;
    active &= i <= r.n;
  }
  intN refine = hit > 0;
  if (REFINE_STEPS > 0 && any(refine)) {
    floatN a = sample_tN(&r, hit - 1, step), b = t_hit;
    for (int k = 0; k < REFINE_STEPS; ++k) {
      floatN m = 0.5f * (a + b);
      floatN v = sampleN(vol, P, r.ox + m * r.dx, r.oy + m * r.dy, r.oz + m * r.dz);
      intN in = (v >= lo) & (v <= hi);
      b = select(b, m, in);
      a = select(m, a, in);
    }
    t_hit = select(t_hit, 0.5f * (a + b), refine);
    samples += select((intN)(0), (intN)(REFINE_STEPS), refine);
  }
  floatN hx = r.ox + t_hit * r.dx, hy = r.oy + t_hit * r.dy, hz = r.oz + t_hit * r.dz;
  intN has_hit = hit >= 0;
  VecN color = {P->background.x, P->background.y, P->background.z};
  if (any(has_hit)) {
    floatN c[4];
    lutN(lut, P, sampleN(vol, P, hx, hy, hz), c);
    VecN surface = {c[0], c[1], c[2]};
    if (SHADING) {
      // The gradient where the ray hits the surface; a ray that starts inside the surface
      // at a clip face shades the cut as a flat cap facing along that face's axis.
      VecN at = {hx, hy, hz};
      VecN g = volume_gradientN(vol, P, at);
      intN cap = (hit == 0) & (axis >= 0);
      intN graded = (hit > 0) | ((hit == 0) & (axis < 0));
      VecN n = {cap_or_gradientN(g.x, graded, cap, axis == 0),
                cap_or_gradientN(g.y, graded, cap, axis == 1),
                cap_or_gradientN(g.z, graded, cap, axis == 2)};
      samples += select((intN)(0), (intN)(GRADIENT_TAPS), graded);
      VecN normal = gradient_to_worldN(P, n);
      VecN pos = {world[0] + t_hit * world[3], world[1] + t_hit * world[4],
                  world[2] + t_hit * world[5]};
      VecN view = {-world[3], -world[4], -world[5]};
      surface = shadeN(surface, normal, pos, view, P->light_w, P->light);
    }
    color.x = select(color.x, surface.x, has_hit);
    color.y = select(color.y, surface.y, has_hit);
    color.z = select(color.z, surface.z, has_hit);
  }
  write_packet(P, out, count, gx, gy, color, samples);
}

// After RayPacket and lutN, which it uses.
#include "shade_queue.cl"

// One dvr sample into the composite: opacity (and colour) c of the segment of length seg
// at t, for the lanes in `live`. Updates alpha, active, samples and the colour (acc, or
// the shading queue).
inline void dvr_compositeN(__global const short* restrict vol, __constant RaycastParams* P,
                           __global const float4* lut, ShadeQueue* queue, floatN acc[3],
                           floatN* alpha, intN* active, intN* samples, intN live, floatN seg,
                           floatN t, floatN value, const floatN c[4]) {
  *samples -= live;
  intN seen = live & (c[3] > 0.0f);
  if (!any(seen)) return;
  floatN a = c[3];
  if (OPACITY_CORRECTION) {
    floatN ratio = seg / P->view.w;
    a = CORRECTED_OPACITY_BY(a, ratio, fast_log2N, fast_exp2N);
  }
  floatN w = select((floatN)(0.0f), (1.0f - *alpha) * a, seen);
  if (SHADING) {
    shade_queue_push(vol, P, lut, queue, t, value, w, seen);
    *samples += select((intN)(0), (intN)(GRADIENT_TAPS), seen);
  } else {
    for (int ch = 0; ch < 3; ++ch) acc[ch] += w * c[ch];
  }
  *alpha += w;
  *active &= ~(seen & (*alpha >= P->dvr.z));
}

// march_dvr (march.cl) for a packet: the same segments, leaps, opacity and early
// termination lane by lane. Seen samples are shaded LANES at a time (shade_queue.cl).
// DVR_BATCH samples per iteration: the later ones' loads need not wait for the first's
// compositing (a lane that ends early drops the rest). 2 ran about 5 % faster than 1;
// 3 and 4 no faster than 2 (CThead, VTK's orbit).
#define DVR_BATCH 2
inline void dvr_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global const float4* lut, __global uchar4* out, CELL_ARGS,
                       __global uint* count, int gx, int gy) {
  float step = P->view.z;
  RayPacket r;
  floatN world[6];
  pixel_raysN(P, gx, gy, &r, world);
  floatN acc[3] = {0.0f, 0.0f, 0.0f}, alpha = 0.0f;
  intN i = 0, check = 0, samples = 0;
  intN active = r.n >= 0;
  ShadeQueue queue;
  if (SHADING) shade_queue_init(&queue, &r, world);
  while (any(active)) {
    if (ESS) {
      // Waiting for every lane took 3 % less CPU time than iso's half (CThead, VTK's
      // transfer function, both orbits).
      active = leap_packetN(leap, range, P, &r, &i, &check, active, step, true, true);
      if (!any(active)) break;
    }
    floatN sa[DVR_BATCH], sb[DVR_BATCH], t[DVR_BATCH], value[DVR_BATCH], c[DVR_BATCH][4];
    intN live[DVR_BATCH];
    for (int k = 0; k < DVR_BATCH; ++k) {
      segmentN(&r, i + k, step, &sa[k], &sb[k]);
      live[k] =
          active & (i + k <= r.n) & (sb[k] - sa[k] > 0.0f);  // segment 0 without jitter is empty
      t[k] = 0.5f * (sa[k] + sb[k]);
      value[k] = sampleN(vol, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy, r.oz + t[k] * r.dz);
      if (SHADING)
        c[k][3] = lut_alphaN(lut, P, value[k]);
      else
        lutN(lut, P, value[k], c[k]);
    }
    for (int k = 0; k < DVR_BATCH; ++k)
      dvr_compositeN(vol, P, lut, &queue, acc, &alpha, &active, &samples, live[k] & active,
                     sb[k] - sa[k], t[k], value[k], c[k]);
    i += DVR_BATCH;
    active &= i <= r.n;
  }
  if (SHADING) {
    if (queue.n > 0) shade_queue_flush(vol, P, lut, &queue, queue.n);
    for (int ch = 0; ch < 3; ++ch) acc[ch] = vloadN(0, queue.acc[ch]);
  }
  VecN color = {acc[0] + (1.0f - alpha) * P->background.x,
                acc[1] + (1.0f - alpha) * P->background.y,
                acc[2] + (1.0f - alpha) * P->background.z};
  write_packet(P, out, count, gx, gy, color, samples);
}

// Steps of the cell walk a mip packet keeps (floatN x 3 each in private memory: 24 KiB,
// 256 steps at 8 lanes); a ray that crosses more cells takes the walk-as-you-go loop instead.
#define MIP_WALK (2048 / LANES)

// Walks every lane's cells in order (a 3D DDA by exit planes, no samples) and keeps step
// g's cell in max[g], t_in[g], t_out[g], its max as -FLT_MAX where it cannot show above
// the window's low end. Returns the number of steps, or -1 when a ray needs more.
inline int walk_cellsN(__global const short2* range, __constant RaycastParams* P,
                       const RayPacket* r, float low, floatN* max, floatN* t_in, floatN* t_out) {
  floatN nudge = 1e-3f / fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  floatN t = r->t0, t_enter = r->t0;
  intN pending = r->n >= 0;
  int g = 0;
  for (; any(pending); ++g) {
    if (g == MIP_WALK) return -1;
    intN cx, cy, cz;
    intN k = cellN(P, r, t, pending, &cx, &cy, &cz);
    floatN t_exit = fmin(cube_exitN(P, r, cx, cy, cz, 0), r->t1);
    floatN m = cell_maxN(range, k);
    max[g] = select((floatN)(-FLT_MAX), m, pending & (m > low));
    t_in[g] = t_enter;
    t_out[g] = t_exit;
    pending &= t_exit < r->t1;
    t_enter = select(t_enter, t_exit, pending);
    t = select(t, fmax(t, t_exit) + fmax(nudge, fabs(t_exit) * 5e-7f), pending);
  }
  return g;
}

// Lane l of v[g] for each lane's own step g = at.sl.
inline floatN pickN(const floatN* v, intN at) {
  const float* f = (const float*)v;
#define PICK_LANE(l, n) f[at.s##l * LANES + n]
  return (floatN)(LANE_LIST(PICK_LANE));
#undef PICK_LANE
}

// Samples j ... end for the lanes in `todo`, raising *vmax until it reaches the window's
// high end; with trilinear, the rest of a voxel cell whose eight voxels cannot raise the
// lane's floor (its maximum, or the window's low end) is skipped.
inline void sample_spanN(__global const short* restrict vol, __constant RaycastParams* P,
                         const RayPacket* r, intN j, intN end, intN todo, float low, float high,
                         floatN* vmax, intN* samples) {
  float step = P->view.z;
  todo &= j <= end;
  while (any(todo)) {
    floatN t = sample_tN(r, j, step);
    floatN vlo, vhi;
    floatN v =
        sample_rangeN(vol, P, r->ox + t * r->dx, r->oy + t * r->dy, r->oz + t * r->dz, &vlo, &vhi);
    *samples -= todo;
    *vmax = select(*vmax, fmax(*vmax, v), todo);
    todo &= *vmax < high;
    intN cell_below = todo & (vhi <= fmax(*vmax, low));
    if (INTERP != 0 && any(cell_below) != 0)
      j = select(j + 1, max(j + 1, past_voxel_cellN(r, t, step)), cell_below);
    else
      j += 1;
    todo &= j <= end;
  }
}

// march_mip (march.cl) for a packet. Only what can change the windowed grey is
// sampled: values at or below the window's low end show black, so the running maximum
// starts there for skipping; a lane stops once it reaches the window's high end (white);
// and with trilinear the rest of a voxel cell whose eight voxels cannot exceed the lane's
// floor is skipped. Each is exact: the grey of every pixel is unchanged.
inline void mip_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global uchar4* out, CELL_ARGS, __global uint* count, int gx, int gy) {
  float step = P->view.z;
  RayPacket r;
  floatN world[6];
  pixel_raysN(P, gx, gy, &r, world);
  float low = P->dvr.x, high = P->dvr.x + 1.0f / P->dvr.y;
  floatN vmax = -FLT_MAX;
  intN i = 0, check = 0, samples = 0;
  intN active = r.n >= 0;
  if (ESS) {
    // The maximum does not depend on the order of the samples: walk the cells once, then
    // sample them brightest first, until no cell left can raise a lane's maximum (or
    // show above the window's low end). Most rays sample a few cells.
    floatN cell_max[MIP_WALK], t_in[MIP_WALK], t_out[MIP_WALK];
    int steps = walk_cellsN(range, P, &r, low, cell_max, t_in, t_out);
    if (steps >= 0) {
      while (any(active)) {
        floatN best = -FLT_MAX;
        intN at = 0;
        for (int g = 0; g < steps; ++g) {
          intN better = cell_max[g] > best;
          best = select(best, cell_max[g], better);
          at = select(at, (intN)(g), better);
        }
        active &= best > fmax(vmax, low);
        if (!any(active)) break;
        float* m = (float*)cell_max;  // taken: lane l of step at.sl
#define TAKE_LANE(l, n) m[at.s##l * LANES + n] = -FLT_MAX;
        LANE_EACH(TAKE_LANE)
#undef TAKE_LANE
        // The samples with t in [t_in, t_out), up to the last one at t1. One that rounding
        // puts in the neighbouring cell is within a voxel of the face, and so within
        // that cell's max (its apron): leaving it to that cell is exact.
        floatN from = pickN(t_in, at), to = pickN(t_out, at);
        intN end = select(index_atN(&r, to, step, false) - 1, r.n, to >= r.t1);
        sample_spanN(vol, P, &r, index_atN(&r, from, step, false), end, active, low, high, &vmax,
                     &samples);
        active &= vmax < high;
      }
    }
  }
  // Without ESS, or for a ray that crosses more cells than the walk keeps: in order, a
  // span at a time between leaps past cells that cannot raise a lane's floor.
  while (any(active)) {
    intN end = r.n;
    if (ESS) {
      floatN floor_v = fmax(vmax, low);
      i = select(i, ess_leapN(leap, range, P, &r, i, active, step, false, true, floor_v, &check),
                 active);
      active &= i <= r.n;
      if (!any(active)) break;
      end = min(check - 1, r.n);
    }
    sample_spanN(vol, P, &r, i, end, active, low, high, &vmax, &samples);
    i = end + 1;
    active &= (i <= r.n) & (vmax < high);
  }
  floatN grey = clamp((vmax - low) * P->dvr.y, 0.0f, 1.0f);
  VecN color = {grey, grey, grey};
  write_packet(P, out, count, gx, gy, color, samples);
}

#endif
