// The light grid of LIGHTING 1 (shadows) and 2 (ao): one float per grid point on a coarse
// grid (a point every `cell` voxels, P->light_grid), computed on the device when the light,
// the table, the clip box or the model changes (engine/src/light_volume.cpp), then read per
// shaded sample by frame_light (shading.cl). The models are those of the Monte Carlo
// reference (engine/include/voxray/engine/monte_carlo_reference.h):
//   sigma    the extinction per mm of the classified volume, -ln(1 - a) / reference step,
//            averaged over each grid cell (extinction is what integrates along a ray). iso
//            (light_sigma's `iso`): the surface, opaque in the iso range and clear outside
//            it, as -ln(1 - f) over the cell's edge for the fraction f of the cell inside
//            (iso's table gives every value the surface colour at opacity 1, air too).
//   shadow   exp(-optical depth) from the grid point to the light, in the clip box; the
//            shading reads it the shadow offset (P->light_march.w) toward the light from
//            the sample (frame_light), so that no surface shadows itself.
//   ao       the mean over 16 directions (a Fibonacci sphere) of exp(-optical depth) to
//            P->light_march.x mm, inside the clip box.
// shadows sweeps the sigma grid slice by slice (light_sweep); a light within the grid's
// extent on every axis is marched per point instead (light_shadow, at P->light_march.y mm).
// ao marches each point's directions to the radius (light_ao). The sigma grid is kept for
// the next build when only the light or the model changes.
#include "classification/lut.cl"
#include "intersection/intersect.cl"
#include "reconstruction/sampling.cl"
#include "shading/shading.cl"

#define LIGHT_MAX_DEPTH 20.0f  // exp(-20) = 2e-9: the rest of the ray cannot matter
#define AO_DIRECTIONS 16       // a Fibonacci sphere (light_ao)

inline int3 grid_point(__constant RaycastParams* P, int gid) {
  int4 n = P->light_grid;
  return (int3)(gid % n.x, (gid / n.x) % n.y, gid / (n.x * n.y));
}

// Whether any macro cell (CELL voxels, skip.cl) that voxel positions lo..hi reach is
// occupied for this frame's table (leap 0).
inline bool block_occupied(__constant RaycastParams* P, __global const uchar* leap, float3 lo,
                           float3 hi) {
  int3 a = clamp(convert_int3(floor(lo)) / CELL, (int3)(0), P->cells.xyz - 1);
  int3 b = clamp(convert_int3(floor(hi)) / CELL + 1, (int3)(0), P->cells.xyz - 1);
  for (int z = a.z; z <= b.z; ++z)
    for (int y = a.y; y <= b.y; ++y)
      for (int x = a.x; x <= b.x; ++x)
        if (leap[(z * P->cells.y + y) * P->cells.x + x] == 0) return true;
  return false;
}

// use_leap: dvr frames with empty-space skipping, whose occupancy (leap) is that of this
// table's opacities: a cell only transparent voxels reach has sigma 0 without reading them.
// iso: the frame is iso (the occluder is the iso range, not the table).
__kernel void light_sigma(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                          __global const uchar* leap, int use_leap, int iso, __global float* sigma,
                          int points) {
  int gid = get_global_id(0);
  if (gid >= points) return;
  float cell = (float)P->light_grid.w;
  // 2 sub-samples per axis at most: placed between voxels, each trilinear sample is the mean
  // of a 2x2x2 block, so 8 reads cover a cell of 4 voxels (64 voxel reads cost 8x the time).
  int sub = min(P->light_grid.w, 2);
  float spacing = cell / (float)sub, shift = spacing >= 2.0f ? 0.5f : 0.0f;
  float3 base = convert_float3(grid_point(P, gid)) * cell - 0.5f * cell + 0.5f * spacing - shift;
  float3 hi = convert_float3(P->dims.xyz - 1);
  float sum = 0.0f;
  if (use_leap && !block_occupied(P, leap, base - 1.0f, base + cell + 1.0f)) {
    sigma[gid] = 0.0f;
    return;
  }
  int inside = 0;
  for (int z = 0; z < sub; ++z)
    for (int y = 0; y < sub; ++y)
      for (int x = 0; x < sub; ++x) {
        float3 p = clamp(base + (float3)(x, y, z) * spacing, (float3)(0.0f), hi);
        float value = sample_volume(VOLUME, P, p);
        if (iso) {
          inside += in_iso(P, value);
        } else {
          float a = clamp(lut_lookup(lut, P, value).w, 0.0f, 0.999999f);
          sum += -log(1.0f - a);
        }
      }
  float samples = (float)(sub * sub * sub);
  // iso: the surface is opaque where it is, so a ray crossing a cell that fraction f of it
  // fills passes with 1 - f, -ln(1 - f) over the cell's edge. The mean extinction (an opaque
  // sample's over a reference step, times f) closed a cell the surface only touches: it
  // grew every bone by about a cell, and its shadows over the lit surfaces near it.
  float f = min((float)inside / samples, 0.999999f);
  float mean = iso ? -log(1.0f - f) / cell : sum / samples;
  // What the clip box removes casts no shadow (at the grid's resolution for the sweep).
  float3 g = convert_float3(grid_point(P, gid)) * cell;
  bool kept = all(g >= P->clip_lo.xyz - 0.5f * cell) && all(g <= P->clip_hi.xyz + 0.5f * cell);
  sigma[gid] = kept ? mean / P->view.w : 0.0f;
}

// exp(-optical depth) from voxel position p along dv (voxels per mm), from `skip` to
// `length` mm.
inline float grid_transmittance(__constant RaycastParams* P, __global const float* sigma, float3 p,
                                float3 dv, float skip, float length) {
  float t0, t1;
  if (intersect_box(p, dv, P->clip_lo.xyz, P->clip_hi.xyz, &t0, &t1) < -1) return 1.0f;
  float a = fmax(t0, skip), b = fmin(t1, length);
  if (!(b > a)) return 1.0f;
  int n = (int)clamp(ceil((b - a) / P->light_march.y), 1.0f, 65536.0f);
  float h = (b - a) / (float)n, depth = 0.0f;
  for (int k = 0; k < n && depth < LIGHT_MAX_DEPTH; ++k)
    depth += h * grid_trilinear(sigma, P->light_grid,
                                (p + (a + ((float)k + 0.5f) * h) * dv) * P->light_march.z);
  return exp(-depth);
}

__kernel void light_shadow(__constant RaycastParams* P, __global const float* sigma,
                           __global float* out, int points) {
  int gid = get_global_id(0);
  if (gid >= points) return;
  float3 p = convert_float3(grid_point(P, gid)) * (float)P->light_grid.w, dv;
  float len = toward_light(P, p, &dv);
  out[gid] = len > 0.0f ? grid_transmittance(P, sigma, p, dv, 0.0f, len) : 1.0f;
}

// The grid's value at grid coordinates (u, v) of slice `slice` across axis `axis`, bilinear,
// or `outside` beyond the slice's edge (the path toward the light leaves the volume there).
inline float slice_bilinear(__global const float* t, int4 n, int axis, int slice, float u, float v,
                            float outside) {
  int na[3] = {n.x, n.y, n.z};
  int au = (axis + 1) % 3, av = (axis + 2) % 3;
  float hu = (float)(na[au] - 1), hv = (float)(na[av] - 1);
  if (!(u >= -0.5f && u <= hu + 0.5f && v >= -0.5f && v <= hv + 0.5f)) return outside;
  u = clamp(u, 0.0f, hu), v = clamp(v, 0.0f, hv);
  int u0 = (int)floor(u), v0 = (int)floor(v);
  int u1 = min(u0 + 1, na[au] - 1), v1 = min(v0 + 1, na[av] - 1);
  float fu = u - (float)u0, fv = v - (float)v0;
  int st[3] = {1, n.x, n.x * n.y};
  int base = slice * st[axis];
  float a = t[base + u0 * st[au] + v0 * st[av]], b = t[base + u1 * st[au] + v0 * st[av]];
  float c = t[base + u0 * st[au] + v1 * st[av]], d = t[base + u1 * st[au] + v1 * st[av]];
  return mix(mix(a, b, fu), mix(c, d, fu), fv);
}

// The transmittance from each grid point to the grid's edge toward the light, which lies
// beyond the grid along `axis` (`toward` the side, +1 or -1). Slice by slice from that side:
// a point's value is its neighbour's toward the light (bilinear in the slice before)
// attenuated by the segment's own depth, mean sigma x length. O(points) instead of a march
// per point. Transmittance interpolates across a shadow's edge as the grid should (depth
// would darken every point next to an opaque one). One launch of ONE work-group, which
// loops over the slices with a barrier between them: a launch per slice cost about 13 ms
// each on a loaded 2-core PoCL device (the workers' wake-ups), 1.9 s a sweep.
__kernel void light_sweep(__constant RaycastParams* P, __global const float* sigma,
                          __global float* t, int axis, int toward, int reach) {
  int4 n = P->light_grid;
  int na[3] = {n.x, n.y, n.z};
  int au = (axis + 1) % 3, av = (axis + 2) % 3;
  int across = na[au] * na[av], slices = na[axis];
  int st[3] = {1, n.x, n.x * n.y};
  int lid = get_local_id(0), items = get_local_size(0);
  float cell = (float)n.w;
  for (int i = 0; i < slices; ++i) {
    int slice = toward > 0 ? slices - 1 - i : i, back = min(reach, i);
    for (int j = lid; j < across; j += items) {
      int g[3];
      g[axis] = slice, g[au] = j % na[au], g[av] = j / na[au];
      int index = g[2] * st[2] + g[1] * st[1] + g[0];
      if (i == 0) {
        t[index] = 1.0f;  // the slice nearest the light: nothing lies before it
        continue;
      }
      float3 p = (float3)(g[0], g[1], g[2]) * cell;
      float3 du = P->light_v.xyz - p;
      float d[3] = {du.x, du.y, du.z};
      // du / |d_axis| cell: the step to the next slice toward the light, in voxels (finite
      // for a light at "infinity": both factors are scaled by the same huge length).
      float3 step = du * (cell / fabs(d[axis]));
      float3 q = p / cell, dq = step / cell;  // grid coordinates
      // The depth over `back` slices (trapezoids at each slice crossing), then the
      // transmittance there: one interpolation of it per `back` slices, not per slice.
      float s0 = sigma[index], depth = 0.0f;
      for (int k = 1; k <= back; ++k) {
        q += dq;
        float qa[3] = {q.x, q.y, q.z};
        float s1 = slice_bilinear(sigma, n, axis, slice + k * toward, qa[au], qa[av], 0.0f);
        depth += 0.5f * (s0 + s1);
        s0 = s1;
      }
      float qa[3] = {q.x, q.y, q.z};
      float tq = slice_bilinear(t, n, axis, slice + back * toward, qa[au], qa[av], 1.0f);
      t[index] = tq * exp(-depth * voxel_mm(P, step));
    }
    barrier(CLK_GLOBAL_MEM_FENCE);  // the next slice reads this one
  }
}

// ao: the visibility at every `every`-th grid point per axis (a lattice of n points, x
// fastest), the mean over AO_DIRECTIONS directions (a Fibonacci sphere) of exp(-depth to
// P->light_march.x mm), marched over the sigma grid a cell per step. A march per point
// and direction: the radius spans a few cells, so it reads less than a sweep of the whole
// grid per direction did (16 sweeps of a launch per slice: 24 s on the 512x512x400 CT).
__kernel void light_ao(__constant RaycastParams* P, __global const float* sigma,
                       __global float* out, int4 n, int every) {
  int gid = get_global_id(0);
  if (gid >= n.x * n.y * n.z) return;
  int3 c = (int3)(gid % n.x, (gid / n.x) % n.y, gid / (n.x * n.y));
  int3 g = min(c * every, P->light_grid.xyz - 1);
  float3 p = convert_float3(g) * (float)P->light_grid.w;
  float sum = 0.0f;
  for (int i = 0; i < AO_DIRECTIONS; ++i) {
    float z = 1.0f - (2.0f * (float)i + 1.0f) / (float)AO_DIRECTIONS;
    float r = sqrt(fmax(0.0f, 1.0f - z * z)), phi = 2.39996322972865332f * (float)i;
    float3 w = (float3)(r * cos(phi), r * sin(phi), z);
    // World to voxels per mm: the gradient matrix's rows are worldToVoxel's columns.
    float3 dv = w.x * P->grad_x.xyz + w.y * P->grad_y.xyz + w.z * P->grad_z.xyz;
    sum += grid_transmittance(P, sigma, p, dv, 0.0f, P->light_march.x);
  }
  out[gid] = sum / (float)AO_DIRECTIONS;
}

// The grid from the lattice of light_ao (n points, one every `every` grid points),
// trilinear: ao varies over the radius, several cells.
__kernel void light_ao_fill(__constant RaycastParams* P, __global const float* lattice,
                            __global float* out, int4 n, int every) {
  int gid = get_global_id(0);
  int4 m = P->light_grid;
  if (gid >= m.x * m.y * m.z) return;
  out[gid] = grid_trilinear(lattice, n, convert_float3(grid_point(P, gid)) / (float)every);
}
