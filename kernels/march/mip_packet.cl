// march_mip (march.cl) for packets of rays (march_lanes.cl): the same maximum per pixel,
// the macro cells walked once and sampled brightest first.
#ifndef VOXRAY_MIP_PACKET_CL
#define VOXRAY_MIP_PACKET_CL

#include "empty_space/skip_lanes.cl"
#include "intersection/ray_lanes.cl"
#include "march/march_lanes.cl"
#include "reconstruction/sampling_lanes.cl"

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
