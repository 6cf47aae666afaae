// Occupancy of the macro cells for one frame's iso range or transfer function, run only
// when those change (engine/src/empty_space.cpp). One work-item per cell; range holds
// each cell's min/max with its apron (skip.cl says why). Conservative on purpose: a cell
// that might matter is occupied; half a stored unit and one table entry of margin absorb
// float rounding of samples and table positions.
//   iso (classify, mode 0): occupied when [min, max] meets the iso range P->values.xy
//   mip (classify, mode 2): occupied when the cell's max is above the grey window's low end
//                 P->dvr.x (anything at or below it shows black, like no sample at all)
//   dvr (classify_dvr): occupied when a table entry the cell's values can interpolate from
//                 has opacity > 0; the host folds that test per stored value
//                 (engine/src/dvr_occupancy.h)
#include "params.cl"

__kernel void classify(__global const short2* range, __constant RaycastParams* P, int mode,
                       int cells, __global uchar* occ) {
  int k = get_global_id(0);
  if (k >= cells) return;
  float lo = range[k].x - 0.5f, hi = range[k].y + 0.5f;
  occ[k] = mode == 0 ? hi >= P->values.x && lo <= P->values.y : hi > P->dvr.x;
}

// bounds: from[0 .. count) then to[0 .. count) (DvrCellBounds), for stored values lo + i. A
// cell whose min is above its max (label-aware dvr's cells where no label shows) is empty.
__kernel void classify_dvr(__global const short2* range, __global const int* bounds, int lo,
                           int count, int cells, __global uchar* occ) {
  int k = get_global_id(0);
  if (k >= cells) return;
  short2 r = range[k];
  int a = clamp(r.x - lo, 0, count - 1), b = clamp(r.y - lo, 0, count - 1);
  occ[k] = r.x <= r.y && bounds[count + b] > bounds[a];
}

// Fused dvr (issue 36): the cells where the overlay may show (engine/src/overlay_cells.h)
// are occupied whatever the volume's values, so a cell is leapt only when both are empty.
__kernel void occupy(__global const uchar* overlay, int cells, __global uchar* occ) {
  int k = get_global_id(0);
  if (k < cells && overlay[k]) occ[k] = 1;
}

// The chessboard (L-infinity) distance of each cell to the nearest occupied cell, in cells,
// in three passes, one per axis: out = min over s of max(|s|, in[c + s]) along the axis.
// Three passes (x, y, z) give the exact distance, because a cube is the product of three
// segments. Distances stop at MAX_LEAP: a ray in a cell at distance d may leap the cube of
// radius d - 1 around it. A transfer-function drag reclassifies every frame: on CPUs the
// passes below are the sweeps (z and y linear in the cells, x 16 cells per load), 2-3 ms of
// CPU each on a 512x512x400 CT (128x128x100 cells) where reading the 2 MAX_LEAP + 1 cells
// around each cell one work-item per cell cost 200 ms a pass on PoCL.
#define MAX_LEAP 15
// The one-sided distances (iso packets) reach further: CT 512x512x400 iso frames took 3 % (16
// lanes) and 10 % (8 lanes) less kernel CPU with 31 than with 15, images identical, for about
// 26 ms more CPU per iso change. The two-sided ones (dvr, mip, one ray per work-item) stay at
// MAX_LEAP: dvr and mip frames were no faster at 31.
#define MAX_LEAP_AHEAD 31

// The same passes one work-item per cell, reading the 2 MAX_LEAP + 1 cells around it along
// `axis` (the first pass reads the occupancy itself: from_occ). GPUs run these: 1.6 M
// work-items in step, a whole table update in 0.18-0.22 ms on an H200
// (docs/bench/gpu-h200x2-round7.txt), where the sweeps below leave most of the chip idle.
__kernel void leap_distance(__global const uchar* in, __global uchar* out, int4 cells, int axis,
                            int from_occ) {
  int k = get_global_id(0);
  int n = cells.x * cells.y * cells.z;
  if (k >= n) return;
  int3 c = (int3)(k % cells.x, (k / cells.x) % cells.y, k / (cells.x * cells.y));
  int len = axis == 0 ? cells.x : axis == 1 ? cells.y : cells.z;
  int pos = axis == 0 ? c.x : axis == 1 ? c.y : c.z;
  int stride = axis == 0 ? 1 : axis == 1 ? cells.x : cells.x * cells.y;
  int best = MAX_LEAP;
  for (int s = max(-MAX_LEAP, -pos); s <= min(MAX_LEAP, len - 1 - pos); ++s) {
    int v = in[k + s * stride];
    int d = from_occ ? (v ? 0 : MAX_LEAP) : v;
    best = min(best, max(s < 0 ? -s : s, d));
  }
  out[k] = (uchar)best;
}

// The sweeps (CPUs): z from the occupancy, then y, then x, each linear in the cells and each
// work-item on 16 cells side by side along x (one uchar16, contiguous loads and stores).
#define LEAP_LANES 16
inline uchar16 leap_load(__global const uchar* p, int lanes) {
  if (lanes == LEAP_LANES) return vload16(0, p);
  uchar t[LEAP_LANES];
  for (int i = 0; i < LEAP_LANES; ++i) t[i] = i < lanes ? p[i] : (uchar)MAX_LEAP;
  return vload16(0, t);
}
inline void leap_store(uchar16 v, __global uchar* p, int lanes) {
  if (lanes == LEAP_LANES) {
    vstore16(v, 0, p);
    return;
  }
  uchar t[LEAP_LANES];
  vstore16(v, 0, t);
  for (int i = 0; i < lanes; ++i) p[i] = t[i];
}

// The z pass (from_occ: in is the occupancy, nonzero occupied) or the y pass (on the z pass's
// distances), along `axis` (1: y, 2: z). One work-item per 16 lines. From the occupancy, each
// sweep counts the cells since the last occupied one. Otherwise, sweeping one way, w[j] is the
// minimum of in over the last j + 1 cells, and the distance from that side is min over j of
// max(j, w[j]) (j = MAX_LEAP always holds). The second sweep takes the minimum with the first.
__kernel void leap_distance_lanes(__global const uchar* in, __global uchar* out, int4 cells,
                                  int axis, int from_occ) {
  int groups = (cells.x + LEAP_LANES - 1) / LEAP_LANES;
  int k = get_global_id(0);
  int other = axis == 1 ? cells.z : cells.y;  // lines across x and the pass's axis
  if (k >= groups * other) return;
  int x0 = (k % groups) * LEAP_LANES, o = k / groups;
  int lanes = min(LEAP_LANES, cells.x - x0);
  int len = axis == 1 ? cells.y : cells.z;
  size_t stride = axis == 1 ? (size_t)cells.x : (size_t)cells.x * cells.y;
  size_t start = (axis == 1 ? (size_t)o * cells.x * cells.y : (size_t)o * cells.x) + x0;
  in += start;
  out += start;
  const uchar16 cap = (uchar16)(MAX_LEAP);
  for (int sweep = 0; sweep < 2; ++sweep) {
    if (from_occ) {
      uchar16 d = cap;
      for (int i = 0; i < len; ++i) {
        size_t at = (size_t)(sweep == 0 ? i : len - 1 - i) * stride;
        d = select(min(d + (uchar16)(1), cap), (uchar16)(0),
                   leap_load(in + at, lanes) != (uchar16)(0));
        leap_store(sweep == 1 ? min(d, leap_load(out + at, lanes)) : d, out + at, lanes);
      }
      continue;
    }
    uchar16 w[MAX_LEAP];
#pragma unroll
    for (int j = 0; j < MAX_LEAP; ++j) w[j] = cap;
    for (int i = 0; i < len; ++i) {
      size_t at = (size_t)(sweep == 0 ? i : len - 1 - i) * stride;
      uchar16 v = leap_load(in + at, lanes);
#pragma unroll
      for (int j = MAX_LEAP - 1; j > 0; --j) w[j] = min(w[j - 1], v);
      w[0] = v;
      uchar16 best = cap;
#pragma unroll
      for (int j = 0; j < MAX_LEAP; ++j) best = min(best, max((uchar16)((uchar)j), w[j]));
      if (sweep == 1) best = min(best, leap_load(out + at, lanes));
      leap_store(best, out + at, lanes);
    }
  }
}

// The x pass, on the y pass's distances: one work-item per 16 cells of a line along x,
// out = min over |s| < MAX_LEAP of max(|s|, in[x + s]) from 2 MAX_LEAP - 1 unaligned loads
// of 16 (|s| = MAX_LEAP is the cap itself). Near the line's ends, from a copy in which the
// cells beyond the line are the cap.
__kernel void leap_distance_rows(__global const uchar* in, __global uchar* out, int4 cells) {
  int groups = (cells.x + LEAP_LANES - 1) / LEAP_LANES;
  int k = get_global_id(0);
  if (k >= groups * cells.y * cells.z) return;
  int x0 = (k % groups) * LEAP_LANES, lanes = min(LEAP_LANES, cells.x - x0);
  size_t line = (size_t)(k / groups) * cells.x;
  in += line;
  const int reach = MAX_LEAP - 1;
  uchar16 best = (uchar16)(MAX_LEAP);
  if (x0 >= reach && x0 + LEAP_LANES + reach <= cells.x) {
#pragma unroll
    for (int s = -reach; s <= reach; ++s)
      best = min(best, max((uchar16)((uchar)abs(s)), vload16(0, in + x0 + s)));
  } else {
    uchar t[LEAP_LANES + 2 * (MAX_LEAP - 1)];
    for (int j = 0; j < LEAP_LANES + 2 * reach; ++j) {
      int x = x0 - reach + j;
      t[j] = x >= 0 && x < cells.x ? in[x] : (uchar)MAX_LEAP;
    }
#pragma unroll
    for (int s = -reach; s <= reach; ++s)
      best = min(best, max((uchar16)((uchar)abs(s)), vload16(0, t + reach + s)));
  }
  leap_store(best, out + line + x0, lanes);
}

// The one-sided twin of the passes above for iso packets (skip_ahead_lanes.cl): along `axis`,
// out = min over 0 <= s <= MAX_LEAP_AHEAD of max(s, in[c + sign s]), only ahead in `sign`'s
// direction. Three passes, one per axis with that octant's signs, give the chessboard
// distance to the nearest occupied cell in the octant ahead (cells c' with c' - c of the
// octant's signs or 0): a ray whose direction has those signs stays in that octant, so it
// may leap the box of d cells ahead (the cell itself and d - 1 more along each axis), where
// the two-sided distance allows only the cube of radius d - 1 around it. Near bone, most
// occupied neighbours lie behind or beside the ray.
// One work-item per line along `axis` (an iso slider drag reclassifies: linear time per
// line instead of up to MAX_LEAP_AHEAD + 1 reads per cell). Walking the line against `sign`,
// near[e] is the distance to the nearest cell ahead whose in is <= e; then out =
// min over e of max(e, near[e]) (e = MAX_LEAP_AHEAD always holds: in <= MAX_LEAP_AHEAD).
// in and out start at in_at and out_at (the passes' regions of two buffers).
__kernel void leap_distance_ahead(__global const uchar* in, int in_at, __global uchar* out,
                                  int out_at, int4 cells, int axis, int from_occ, int sign) {
  int k = get_global_id(0);
  int len = axis == 0 ? cells.x : axis == 1 ? cells.y : cells.z;
  int across = axis == 0 ? cells.y : cells.x;  // lines along the first other axis
  if (k >= cells.x * cells.y * cells.z / len) return;
  int a = k % across, b = k / across;  // the line's other two coordinates, in axis order
  int start = axis == 0   ? (b * cells.y + a) * cells.x
              : axis == 1 ? b * cells.x * cells.y + a
                          : b * cells.x + a;
  int stride = axis == 0 ? 1 : axis == 1 ? cells.x : cells.x * cells.y;
  in += in_at + start;
  out += out_at + start;
  uchar near[MAX_LEAP_AHEAD];
  for (int e = 0; e < MAX_LEAP_AHEAD; ++e) near[e] = MAX_LEAP_AHEAD;
  for (int j = 0; j < len; ++j) {
    int p = sign > 0 ? len - 1 - j : j;
    int v = in[p * stride];
    if (from_occ) {  // in is the occupancy (1: occupied): every near[e] is the distance to it
      near[0] = v ? 0 : min(near[0] + 1, MAX_LEAP_AHEAD);
      out[p * stride] = near[0];
      continue;
    }
    int g = v, best = MAX_LEAP_AHEAD;
    for (int e = 0; e < MAX_LEAP_AHEAD; ++e) {
      int d = g <= e ? 0 : min(near[e] + 1, MAX_LEAP_AHEAD);
      near[e] = (uchar)d;
      best = min(best, max(e, d));
    }
    out[p * stride] = (uchar)best;
  }
}

// The two-sided distances of an iso classification for packets, from the one-sided ones
// (leap_distance_ahead's eight regions behind them): the eight closed octants around a cell
// cover the grid, so the nearest occupied cell is the nearest in one of them. One read per
// octant instead of the three passes above.
__kernel void leap_distance_from_octants(__global uchar* leap, int cells) {
  int k = get_global_id(0);
  if (k >= cells) return;
  uchar d = MAX_LEAP;
  for (int o = 1; o <= 8; ++o) d = min(d, leap[o * cells + k]);
  leap[k] = d;
}

// Adaptive dvr steps (ADAPTIVE, march.cl): whether a segment of f = 4 base steps (h each)
// whose midpoint lies in the cell may replace the 4 segments it covers (level 1) or not (0).
// Their midpoints lie within 3 h / 2 of its own, at most one voxel (march.cl caps f), so every
// sample they take reads voxels of cells c ... c + 1 along each axis (with the lower apron of
// cell c, skip.cl): the level is taken from the values of those 8 cells. The table entries
// those values can interpolate from (classify's margin) have opacities in [amin, amax] and
// colours within dc of each other; the long segment's transmittance then differs from the
// short ones' product by at most (f h / h_ref) (amax - amin) (the derivative of (1 - a)^m in
// a is at most m) and its emitted colour by at most (f h / h_ref) amax dc. Level 1 where
// (f h / h_ref) (amax - amin + amax dc) <= P->dvr.w, the error bound: per long segment, at
// most dvr.w times the transmittance in front of it, in opacity and in each colour channel
// (before shading, whose normals the table does not bound). Where no such entry is opaque,
// level 1 is exact. Writes leap[cells + k] (the levels ride behind the leap distances).
__kernel void adaptive_level(__global const short2* range, __constant RaycastParams* P,
                             __global const float4* lut, int cells, __global uchar* leap) {
  int k = get_global_id(0);
  if (k >= cells) return;
  int4 n = P->cells;
  int3 c = (int3)(k % n.x, (k / n.x) % n.y, k / (n.x * n.y));
  float lo = FLT_MAX, hi = -FLT_MAX;
  for (int dz = 0; dz <= min(1, n.z - 1 - c.z); ++dz)
    for (int dy = 0; dy <= min(1, n.y - 1 - c.y); ++dy)
      for (int dx = 0; dx <= min(1, n.x - 1 - c.x); ++dx) {
        short2 m = range[k + (dz * n.y + dy) * n.x + dx];
        lo = fmin(lo, (float)m.x);
        hi = fmax(hi, (float)m.y);
      }
  lo -= 0.5f, hi += 0.5f;
  int last = P->dims.w - 1;
  float x0 = clamp((lo - P->values.z) * P->values.w, 0.0f, (float)last);
  float x1 = clamp((hi - P->values.z) * P->values.w, 0.0f, (float)last);
  int a = max((int)floor(x0) - 1, 0), b = min((int)floor(x1) + 2, last);
  float4 cmin = lut[a], cmax = lut[a];
  float reach = 4.0f * P->view.z / P->view.w, bound = P->dvr.w;
  for (int e = a + 1; e <= b; ++e) {
    cmin = fmin(cmin, lut[e]);
    cmax = fmax(cmax, lut[e]);
    float3 dc = cmax.xyz - cmin.xyz;
    float worst = (cmax.w - cmin.w) + cmax.w * fmax(dc.x, fmax(dc.y, dc.z));
    if (reach * worst > bound && cmax.w > 0.0f) {
      leap[cells + k] = 0;
      return;
    }
  }
  leap[cells + k] = 1;
}
