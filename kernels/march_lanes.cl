// iso, dvr and mip for CPUs: one work-item marches a packet of 4 x PACKET_ROWS neighbouring
// rays in floatN lanes (lanes.cl). PoCL runs a per-ray loop as scalar code, one ray at a
// time; here the arithmetic of LANES rays shares each vector instruction and only the volume loads
// stay scalar. The algorithms are march.cl's lane by lane: the same samples, the same empty-space
// leaps (skip.cl's ess_leap), the same bisection, so the image is the same. Lanes whose ray is done
// are masked; the packet runs until its last ray is. Volumes here are buffers (STORAGE_IMAGE 0) of
// fewer than 2^31 voxels (int indices).
#ifndef VOXRAY_MARCH_LANES_CL
#define VOXRAY_MARCH_LANES_CL

#include "gradients_lanes.cl"
#include "lut_lanes.cl"
#include "march.cl"
#include "ray_lanes.cl"
#include "shade_queue.cl"
#include "skip_ahead_lanes.cl"
#include "skip_lanes.cl"
#if HIT_OUTPUT
#include "hit_output_lanes.cl"
// The kernel's hits, passed on to iso and dvr packets (PACKET_ARGS).
#define PACKET_HITS , __global float4* hits
#define PACKET_HITS_ARG , hits
#else
#define PACKET_HITS
#define PACKET_HITS_ARG
#endif

// What iso and dvr packets take: the kernel's arguments and the packet's place (gx, gy).
#define PACKET_ARGS                                                                            \
  __global const short *restrict vol, __constant RaycastParams *P, __global const float4 *lut, \
      __global uchar4 *out, CELL_ARGS, __global uint *count, int gx, int gy PACKET_HITS

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

// One component of an iso hit's normal: the gradient's where it was taken, the clip
// face's axis at a cap, 0 otherwise.
inline floatN cap_or_gradientN(floatN g, intN graded, intN cap, intN along) {
  floatN zero = 0.0f;
  return select(select(zero, g, graded), select(zero, (floatN)(1.0f), along), cap);
}

// Samples an iso packet loads at once (see iso_packet). Their gathers' misses are most of
// the kernel's time on a large volume; an 8-lane gather issues half the loads of a 16-lane
// one, so 8-lane packets keep four samples in flight (CT 512x512x400: three against two
// about -10 % kernel CPU; four against three -2 % in AVX-512 and in AVX2 builds, where
// session 9 under load could not tell); at 16 lanes three were no faster than two.
#ifndef ISO_BATCH
#define ISO_BATCH (LANES == 8 ? 4 : 2)
#endif
// ISO_BLOCK_TRIES (switches.h, set by the host): empty 2^3 voxel blocks a lane may pass per
// march iteration before it samples. Only 8-lane packets pass them, 4 (CT 512x512x400 kernel
// CPU -8 %, CThead -6 %); 16 lanes gained nothing measurable (the packet still waits for its
// slowest lane) and CThead lost about 3 %.
inline void iso_packet(PACKET_ARGS) {
  float step = P->view.z;
  RayPacket r;
  floatN world[6];
  intN axis = pixel_raysN(P, gx, gy, &r, world);

  float lo = P->values.x, hi = P->values.y;
  intN i = 0, check = 0, hit = -1, samples = 0;
  floatN t_hit = 0.0f;
  intN active = r.n >= 0;
  intN ahead = ahead_baseN(P, &r);  // this ray's one-sided distances (skip_ahead_lanes.cl)
  while (any(active)) {
    if (ESS) {
      active = leap_packetN(leap, range, P, &r, ahead, &i, &check, active, step, false, false);
      if (!any(active)) break;
      // Inside occupied cells, lanes whose next sample lies in a 2^3 voxel block that cannot
      // hold the iso range move past it instead of loading voxels there: the same first hit.
      for (int g = 0; g < ISO_BLOCK_TRIES; ++g) {
        floatN t = sample_tN(&r, i, step);
        floatN x = r.ox + t * r.dx, y = r.oy + t * r.dy, z = r.oz + t * r.dz;
        intN empty = iso_block_emptyN(leap, P, x, y, z, active);
        if (!any(empty)) break;
        i = select(i, max(i + 1, past_cubeN(&r, x, y, z, 2.0f, step)), empty);
        active &= i <= r.n;
      }
      if (!any(active)) break;
    }
    // ISO_BATCH samples at once: their loads (mostly cache misses on a large volume) are
    // in flight together. Taken in order, the first in the iso range is the hit, the
    // same as one at a time: a later sample that one at a time would have skipped (the
    // rest of a missing voxel cell, or an empty macro cell) cannot be in the range.
    floatN t[ISO_BATCH], v[ISO_BATCH], vlo[ISO_BATCH], vhi[ISO_BATCH];
    for (int k = 0; k < ISO_BATCH; ++k) {
      t[k] = sample_tN(&r, i + k, step);
      v[k] = sample_rangeN(vol, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy, r.oz + t[k] * r.dz,
                           &vlo[k], &vhi[k]);
    }
    intN next = i + ISO_BATCH;
    for (int k = 0; k < ISO_BATCH; ++k) {
      intN live = active & (i + k <= r.n);
      samples -= live;  // true is -1
      intN in = live & (v[k] >= lo) & (v[k] <= hi);
      hit = select(hit, i + k, in);
      t_hit = select(t_hit, t[k], in);
      active &= ~in;
      // Trilinear: a voxel cell whose eight voxels all miss the iso range holds no hit, so
      // the samples left in it are skipped (the same first hit; the one before it, where
      // refinement starts, is outside the range either way).
      intN cell_misses = live & ((vhi[k] < lo) | (vlo[k] > hi));
      if (INTERP != 0 && any(cell_misses) != 0)
        next = select(next, max(next, past_voxel_cellN(&r, t[k], step)), cell_misses);
    }
    i = next;
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
      surface = shade_frameN(lut, P, at, surface, normal, pos, view);
    }
    color.x = select(color.x, surface.x, has_hit);
    color.y = select(color.y, surface.y, has_hit);
    color.z = select(color.z, surface.z, has_hit);
  }
#if HIT_OUTPUT  // march_iso's w: 1 a crossing, 0 the first sample, -1 none
  floatN hit_w = select(select((floatN)(0.0f), (floatN)(1.0f), hit > 0), (floatN)(-1.0f), hit < 0);
  write_hits_packet(P, hits, gx, gy, hx, hy, hz, hit_w);
#endif
  write_packet(P, out, count, gx, gy, color, samples);
}

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

#if ADAPTIVE
// adaptive_segment (march.cl) for the lanes in `live` (f 1 for the others), `reach` as
// adaptive_reach's for each lane.
inline void adaptive_segmentN(__global const uchar* leap, __constant RaycastParams* P,
                              const RayPacket* r, intN i, float step, intN live, intN reach,
                              floatN* a, floatN* b, intN* f) {
  floatN b4, unused;
  segmentN(r, i, step, a, b);
  segmentN(r, i + ADAPTIVE_STEPS - 1, step, &unused, &b4);
  intN cx, cy, cz;
  intN k = cellN(P, r, 0.5f * (*a + b4), live & reach, &cx, &cy, &cz);
  __global const uchar* level = leap + P->cells.x * P->cells.y * P->cells.z;
#define LEVEL_LANE(l, n) level[k.s##l]
  intN longer = live & reach & (convert_intN((ucharN)(LANE_LIST(LEVEL_LANE))) != 0);
#undef LEVEL_LANE
  *f = select((intN)(1), (intN)(ADAPTIVE_STEPS), longer);
  *b = select(*b, b4, longer);
}

// adaptive_reach (march.cl) for each lane.
inline intN adaptive_reachN(const RayPacket* r, float step) {
  floatN dmax = fmax(fabs(r->dx), fmax(fabs(r->dy), fabs(r->dz)));
  return (ADAPTIVE_STEPS - 1) * 0.5f * step * dmax <= 1.0f;
}
#endif

// march_dvr (march.cl) for a packet: the same segments, leaps, opacity and early
// termination lane by lane. Seen samples are shaded LANES at a time (shade_queue.cl).
// DVR_BATCH samples per iteration: the later ones' loads need not wait for the first's
// compositing (a lane that ends early drops the rest). 2 ran about 5 % faster than 1;
// 3 and 4 no faster than 2 (CThead, VTK's orbit).
#define DVR_BATCH 2
inline void dvr_packet(PACKET_ARGS) {
  float step = P->view.z;
  RayPacket r;
  floatN world[6];
  pixel_raysN(P, gx, gy, &r, world);
  floatN acc[3] = {0.0f, 0.0f, 0.0f}, alpha = 0.0f;
  intN i = 0, check = 0, samples = 0;
  intN active = r.n >= 0;
  ShadeQueue queue;
  if (SHADING) shade_queue_init(&queue, &r, world);
#if ADAPTIVE
  intN reach = adaptive_reachN(&r, step);  // long segments allowed (ADAPTIVE)
#endif
#if HIT_OUTPUT
  floatN t_hit = 0.0f;
  intN found = 0;
#endif
  while (any(active)) {
    if (ESS) {
      // Waiting for every lane took 3 % less CPU time than iso's half (CThead, VTK's
      // transfer function, both orbits).
      active = leap_packetN(leap, range, P, &r, (intN)(0), &i, &check, active, step, true, true);
      if (!any(active)) break;
    }
    floatN sa[DVR_BATCH], sb[DVR_BATCH], t[DVR_BATCH], value[DVR_BATCH], c[DVR_BATCH][4];
    intN live[DVR_BATCH];
    intN at = i;
    for (int k = 0; k < DVR_BATCH; ++k) {
#if ADAPTIVE
      intN f;
      adaptive_segmentN(leap, P, &r, at, step, active & (at <= r.n), reach, &sa[k], &sb[k], &f);
#else
      const int f = 1;
      segmentN(&r, at, step, &sa[k], &sb[k]);
#endif
      live[k] = active & (at <= r.n) & (sb[k] - sa[k] > 0.0f);  // segment 0 without jitter is empty
      at += f;
      t[k] = 0.5f * (sa[k] + sb[k]);
      value[k] = sampleN(vol, P, r.ox + t[k] * r.dx, r.oy + t[k] * r.dy, r.oz + t[k] * r.dz);
      if (SHADING)
        c[k][3] = lut_alphaN(lut, P, value[k]);
      else
        lutN(lut, P, value[k], c[k]);
    }
    for (int k = 0; k < DVR_BATCH; ++k) {
#if HIT_OUTPUT
      floatN before = alpha;
#endif
      dvr_compositeN(vol, P, lut, &queue, acc, &alpha, &active, &samples, live[k] & active,
                     sb[k] - sa[k], t[k], value[k], c[k]);
#if HIT_OUTPUT
      dvr_hit_crossingN(before, alpha, sa[k], sb[k], &t_hit, &found);
#endif
    }
    i = at;
    active &= i <= r.n;
  }
  if (SHADING) {
    if (queue.n > 0) shade_queue_flush(vol, P, lut, &queue, queue.n);
    for (int ch = 0; ch < 3; ++ch) acc[ch] = vloadN(0, queue.acc[ch]);
  }
  VecN color = {acc[0] + (1.0f - alpha) * P->background.x,
                acc[1] + (1.0f - alpha) * P->background.y,
                acc[2] + (1.0f - alpha) * P->background.z};
#if HIT_OUTPUT
  write_hits_packet(P, hits, gx, gy, r.ox + t_hit * r.dx, r.oy + t_hit * r.dy, r.oz + t_hit * r.dz,
                    select((floatN)(-1.0f), (floatN)(1.0f), found));
#endif
  write_packet(P, out, count, gx, gy, color, samples);
}

// Steps of the cell walk a mip packet keeps (floatN x 2 each in private memory: 24 KiB at 8
// lanes, 48 KiB at 16); a ray that crosses more cells takes the walk-as-you-go loop
// instead. A ray crosses at most about cells.x + cells.y + cells.z cells, 356 on a
// 512 x 512 x 400 CT. 2048 / LANES steps (128 at 16 lanes) sent many of its rays to the
// slower loop, and larger arrays cost time at 8 lanes (docs/bench/README.md, session 6).
#define MIP_WALK 384  // < MIP_KEY_STEPS

// A walked cell's key: its max times MIP_KEY_STEPS plus MIP_KEY_STEPS - 1 - its step, so
// that the largest key is the brightest cell and, of equal maxima, the first along the ray
// (as before); a lane takes its keys in falling order, so the last one taken is the
// ceiling of the ones left and nothing needs marking. INT_MIN: a cell that cannot show.
#define MIP_KEY_STEPS 512

// Each lane's macro cell k's max, as cell_maxN (skip_lanes.cl) but one gather where the
// device has them (sampling_lanes.cl): a cell's (min, max) is one 32-bit word.
inline floatN walk_cell_maxN(__global const short2* range, intN k) {
#ifdef VOXRAY_GATHER32
  return convert_floatN(gather_wordsN((__global const short*)range, k * 2) >> 16);
#else
  return cell_maxN(range, k);
#endif
}

// Walks every lane's cells in order and keeps step g's cell as key[g] and its span
// [t_at[g], t_at[g + 1]), its key INT_MIN where it cannot show above the window's low end.
// Returns the number of steps, or -1 when a ray needs more. The first cell is the entry
// point's; each step then moves to the neighbour across the exit plane (planes crossed at
// once, through an edge or corner, together), so no step finds its cell from a point. The
// exits are cube_exitN's, from the cell's own planes; the outer cells' outward faces never
// bound, so the walk stays on the grid.
inline int walk_cellsN(__global const short2* range, __constant RaycastParams* P,
                       const RayPacket* r, float low, intN* key, floatN* t_at) {
  intN pending = r->n >= 0;
  intN cx, cy, cz;
  cellN(P, r, r->t0, pending, &cx, &cy, &cz);
  intN sx = select((intN)(-1), (intN)(1), r->dx > 0.0f);
  intN sy = select((intN)(-1), (intN)(1), r->dy > 0.0f);
  intN sz = select((intN)(-1), (intN)(1), r->dz > 0.0f);
  floatN t_enter = r->t0;
  int g = 0;
  for (; any(pending); ++g) {
    if (g == MIP_WALK) return -1;
    intN k = select((intN)(0), (cz * P->cells.y + cy) * P->cells.x + cx, pending);
    floatN ex, ey, ez;
    floatN t_exit = fmin(cube_exit_planesN(P, r, cx, cy, cz, (intN)(0), &ex, &ey, &ez), r->t1);
    floatN m = walk_cell_maxN(range, k);
    key[g] = select((intN)(INT_MIN), convert_intN(m) * MIP_KEY_STEPS + (MIP_KEY_STEPS - 1 - g),
                    pending & (m > low));
    t_at[g] = t_enter;
    t_enter = select(t_enter, fmax(t_enter, t_exit), pending);  // where this step's cell ends
    pending &= t_exit < r->t1;
    cx += sx & pending & (ex <= t_exit);
    cy += sy & pending & (ey <= t_exit);
    cz += sz & pending & (ez <= t_exit);
  }
  t_at[g] = t_enter;
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

// A mip lane with no span left takes its next cell when at least 1 / MIP_REFILL of the
// active lanes wait, so that the packet's lanes keep sampling while one finishes a long
// span (before, every lane waited for the packet's longest span). Each refill scans every
// walked cell: refilling at every idle lane ran slower, at 1 / 4 no faster than at half
// (16 lanes). 8 lanes with two packets a work-item (MIP_HALVES): at 1 / 4 (2 of 8 lanes)
// CT kernel CPU -4 %, CThead -5 % (docs/bench/README.md, session 9).
#ifndef MIP_REFILL
#define MIP_REFILL (LANES == 8 ? 4 : 2)
#endif
#ifndef MIP_BATCH
#define MIP_BATCH 4
#endif
#ifndef MIP_PREFETCH
#define MIP_PREFETCH 1
#endif
#ifndef MIP_PREFETCH_FROM
#define MIP_PREFETCH_FROM 1
#endif
#ifndef MIP_PREFETCH_TO
#define MIP_PREFETCH_TO 1
#endif

// Prefetches (__builtin_prefetch) the four voxel rows of sample i of each lane in `todo`.
inline void prefetch_sample_rowsN(__global const short* restrict vol, __constant RaycastParams* P,
                                  const RayPacket* r, intN i, intN todo) {
  floatN tp = sample_tN(r, i, P->view.z);
  int4 dims = P->dims;
  intN px = clamp(convert_intN(r->ox + tp * r->dx), 0, dims.x - 1);
  intN py = clamp(convert_intN(r->oy + tp * r->dy), 0, dims.y - 1);
  intN pz = clamp(convert_intN(r->oz + tp * r->dz), 0, dims.z - 2);
  intN at = select((intN)(-1), (pz * dims.y + py) * dims.x + px, todo);
  size_t sz = (size_t)dims.x * dims.y;
#define PREFETCH_LANE(l, n)                          \
  if (at.s##l >= 0) {                                \
    __builtin_prefetch(vol + at.s##l);               \
    __builtin_prefetch(vol + at.s##l + dims.x);      \
    __builtin_prefetch(vol + at.s##l + sz);          \
    __builtin_prefetch(vol + at.s##l + sz + dims.x); \
  }
  LANE_EACH(PREFETCH_LANE)
#undef PREFETCH_LANE
}

// MIP_HALVES (switches.h, set by the host, which sizes the grid by it): packets a mip
// work-item marches together, at 8 lanes two 4 x 2 packets (4 x 4 pixels), so that each turn
// has 16 rays' voxel loads in flight, as a 16-lane packet has; the two are otherwise
// independent.

inline bool any_halfN(const intN* m) {
  intN u = m[0];
  for (int h = 1; h < MIP_HALVES; ++h) u |= m[h];
  return any(u) != 0;
}

// Samples each lane's walked cells brightest first, until no cell left can raise its
// maximum (or show above the window's low end). Each lane has its own span [j, end]: the
// cells a lane samples and in what order depend on its own maximum only, so the samples
// are those of taking the cells packet-wide in turns. Each of the MIP_HALVES packets has
// its own walk, refills and skips; their turns' samples are taken together. A packet
// whose walk did not fit (steps < 0) is left to the in-order loop with its lanes active.
inline void mip_cells_brightest_firstN(__global const short* restrict vol,
                                       __constant RaycastParams* P, const RayPacket* r,
                                       const int* steps, intN (*key)[MIP_WALK],
                                       floatN (*t_at)[MIP_WALK + 1], float low, float high,
                                       floatN* vmax, intN* active, intN* samples) {
  float step = P->view.z;
  intN j[MIP_HALVES], end[MIP_HALVES], ceiling[MIP_HALVES], act[MIP_HALVES];
  for (int h = 0; h < MIP_HALVES; ++h) {
    j[h] = 0, end[h] = -1, ceiling[h] = INT_MAX;
    act[h] = steps[h] >= 0 ? active[h] : (intN)(0);
  }
  while (any_halfN(act)) {
    intN todo[MIP_HALVES];
    for (int h = 0; h < MIP_HALVES; ++h) {
      intN idle = act[h] & (j[h] > end[h]);
      int waiting = count_lanes(idle);
      if (waiting > 0 && MIP_REFILL * waiting >= count_lanes(act[h])) {
        // Each lane's largest key below its ceiling; a cell can raise the lane's floor when
        // its (integer) max exceeds it, that is when its key is at least floor_key.
        // Dropping rows no lane can use any more, on the way, scanned 56 % fewer rows but
        // ran slower.
        floatN floor_v = clamp(fmax(vmax[h], low), -65536.0f, 65536.0f);
        intN floor_key = (convert_intN(floor(floor_v)) + 1) * MIP_KEY_STEPS;
        intN best = INT_MIN;
        for (int g = 0; g < steps[h]; ++g) {
          intN k = key[h][g];
#if defined(__AVX512F__)
          best = select(best, max(best, k), k < ceiling[h]);  // one masked max
#else
          // Without mask registers (AVX2) a select on the running best puts a compare
          // and a blend on the loop's chain; here only the max is (mip 8 lanes -10 %).
          best = max(best, select((intN)(INT_MIN), k, k < ceiling[h]));
#endif
        }
        act[h] &= ~(idle & (best < floor_key));
        idle &= act[h];
        ceiling[h] = select(ceiling[h], best, idle);
        intN at = MIP_KEY_STEPS - 1 - (best & (MIP_KEY_STEPS - 1));
        // The samples with t in [t_at[at], t_at[at + 1]), up to the last one at t1. One
        // that rounding puts in the neighbouring cell is within a voxel of the face, and so
        // within that cell's max (its apron): leaving it to that cell is exact.
        at = select((intN)(0), at, idle);
        floatN from = pickN(t_at[h], at), to = pickN(t_at[h], at + 1);
        j[h] = select(j[h], index_atN(&r[h], from, step, false), idle);
        end[h] = select(end[h],
                        select(index_atN(&r[h], to, step, false) - 1, r[h].n, to >= r[h].t1), idle);
      }
      todo[h] = act[h] & (j[h] <= end[h]);
    }
    if (!any_halfN(todo)) continue;
    // MIP_BATCH samples a turn, j ... j + MIP_BATCH - 1: the next turn's addresses depend
    // on this one's loads (the skip below), so each turn waits for its loads; several a turn
    // overlap their misses. Lanes without a sample read the volume's corner, which stays in
    // cache, instead of missing like the others. A sample taken that a skip would have
    // passed cannot change the maximum (it is one of the ray's samples).
    floatN zero = 0.0f, t[MIP_HALVES], vlo, vhi[MIP_HALVES];
    intN take[MIP_HALVES];
    for (int b = 0; b < MIP_BATCH; ++b) {
      for (int h = 0; h < MIP_HALVES; ++h) {
        take[h] = todo[h] & (j[h] + b <= end[h]);
        t[h] = sample_tN(&r[h], j[h] + b, step);
        floatN v = sample_rangeN(vol, P, select(zero, r[h].ox + t[h] * r[h].dx, take[h]),
                                 select(zero, r[h].oy + t[h] * r[h].dy, take[h]),
                                 select(zero, r[h].oz + t[h] * r[h].dz, take[h]), &vlo, &vhi[h]);
        samples[h] -= take[h];
        vmax[h] = select(vmax[h], fmax(vmax[h], v), take[h]);
      }
    }
    for (int h = 0; h < MIP_HALVES; ++h) {
#if MIP_PREFETCH
      // Prefetch the voxel rows of later turns (each one's middle sample's four), so that
      // their misses overlap this turn's instead of waiting on this turn's skip.
      for (int a = MIP_PREFETCH_FROM; a <= MIP_PREFETCH_TO; ++a)
        prefetch_sample_rowsN(vol, P, &r[h], j[h] + a * MIP_BATCH + MIP_BATCH / 2, todo[h]);
#endif
      act[h] &= vmax[h] < high;
      // The rest of the last sample's voxel cell is skipped where its eight voxels cannot
      // raise the lane's floor (a lane without that sample ends its span either way).
      intN cell_below = take[h] & (vhi[h] <= fmax(vmax[h], low));
      if (INTERP != 0 && any(cell_below) != 0)
        j[h] = select(j[h] + MIP_BATCH, max(j[h] + MIP_BATCH, past_voxel_cellN(&r[h], t[h], step)),
                      cell_below);
      else
        j[h] += MIP_BATCH;
    }
  }
  for (int h = 0; h < MIP_HALVES; ++h)
    if (steps[h] >= 0) active[h] = act[h];
}

// march_mip (march.cl) for a packet. Only what can change the windowed grey is
// sampled: values at or below the window's low end show black, so the running maximum
// starts there for skipping; a lane stops once it reaches the window's high end (white);
// and with trilinear the rest of a voxel cell whose eight voxels cannot exceed the lane's
// floor is skipped. Each is exact: the grey of every pixel is unchanged. The work-item's
// MIP_HALVES packets lie one below the other.
inline void mip_packet(__global const short* restrict vol, __constant RaycastParams* P,
                       __global uchar4* out, CELL_ARGS, __global uint* count, int gx, int gy) {
  float step = P->view.z;
  float low = P->dvr.x, high = P->dvr.x + 1.0f / P->dvr.y;
  RayPacket r[MIP_HALVES];
  floatN vmax[MIP_HALVES];
  intN active[MIP_HALVES], samples[MIP_HALVES];
  for (int h = 0; h < MIP_HALVES; ++h) {
    floatN world[6];
    pixel_raysN(P, gx, MIP_HALVES * gy + h, &r[h], world);
    vmax[h] = -FLT_MAX, samples[h] = 0;
    active[h] = r[h].n >= 0;
  }
  if (ESS) {
    // The maximum does not depend on the order of the samples: walk the cells once, then
    // sample them brightest first, until no cell left can raise a lane's maximum (or
    // show above the window's low end). Most rays sample a few cells.
    intN key[MIP_HALVES][MIP_WALK];
    floatN t_at[MIP_HALVES][MIP_WALK + 1];
    int steps[MIP_HALVES];
    for (int h = 0; h < MIP_HALVES; ++h)
      steps[h] = walk_cellsN(range, P, &r[h], low, key[h], t_at[h]);
    mip_cells_brightest_firstN(vol, P, r, steps, key, t_at, low, high, vmax, active, samples);
  }
  for (int h = 0; h < MIP_HALVES; ++h) {
    // Without ESS, or for a ray that crosses more cells than the walk keeps: in order, a
    // span at a time between leaps past cells that cannot raise a lane's floor.
    intN i = 0, check = 0;
    while (any(active[h])) {
      intN end = r[h].n;
      if (ESS) {
        floatN floor_v = fmax(vmax[h], low);
        i = select(i,
                   ess_leapN(leap, range, P, &r[h], (intN)(0), i, active[h], step, false, true,
                             floor_v, &check),
                   active[h]);
        active[h] &= i <= r[h].n;
        if (!any(active[h])) break;
        end = min(check - 1, r[h].n);
      }
      sample_spanN(vol, P, &r[h], i, end, active[h], low, high, &vmax[h], &samples[h]);
      i = end + 1;
      active[h] &= (i <= r[h].n) & (vmax[h] < high);
    }
    floatN grey = clamp((vmax[h] - low) * P->dvr.y, 0.0f, 1.0f);
    VecN color = {grey, grey, grey};
    write_packet(P, out, count, gx, MIP_HALVES * gy + h, color, samples[h]);
  }
}

#endif
