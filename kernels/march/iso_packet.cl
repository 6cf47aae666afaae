// march_iso (march.cl) for a packet of rays (march_lanes.cl): the same samples, leaps,
// first hit and bisection lane by lane, then the hits shaded together.
#ifndef VOXRAY_ISO_PACKET_CL
#define VOXRAY_ISO_PACKET_CL

#include "classification/lut_lanes.cl"
#include "empty_space/skip_ahead_lanes.cl"
#include "empty_space/skip_lanes.cl"
#include "intersection/ray_lanes.cl"
#include "march/march_lanes.cl"
#include "reconstruction/gradients_lanes.cl"
#include "reconstruction/sampling_lanes.cl"

// One component of an iso hit's normal: the gradient's where it was taken, the clip
// face's axis at a cap, 0 otherwise.
inline floatN cap_or_gradientN(floatN g, intN graded, intN cap, intN along) {
  floatN zero = 0.0f;
  return select(select(zero, g, graded), select(zero, (floatN)(1.0f), along), cap);
}

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

#endif
