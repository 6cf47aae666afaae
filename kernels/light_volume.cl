// The light grid of LIGHTING 1 (shadows) and 2 (ao): one float per grid point on a coarse
// grid (a point every `cell` voxels, P->light_grid), computed on the device when the light,
// the table, the clip box or the model changes (engine/src/light_volume.cpp), then read per
// shaded sample by frame_light (shading.cl). The models are those of the Monte Carlo
// reference (engine/include/voxray/engine/monte_carlo_reference.h):
//   sigma    the extinction per mm of the classified volume, -ln(1 - a) / reference step,
//            averaged over each grid cell (extinction is what integrates along a ray).
//   shadow   exp(-optical depth) toward the light, from the shadow offset past the grid
//            point (P->light_march.w: no surface shadows itself) to the light, in the clip box.
//   ao       the mean over 32 directions (a Fibonacci sphere) of exp(-optical depth) to
//            P->light_march.x mm, inside the clip box.
// Both march the sigma grid (trilinear) at P->light_march.y mm, sampling segment midpoints.
#include "intersect.cl"
#include "lut.cl"
#include "sampling.cl"
#include "shading.cl"

#define LIGHT_MAX_DEPTH 20.0f  // exp(-20) = 2e-9: the rest of the ray cannot matter
#define AO_DIRECTIONS 32

inline int3 grid_point(__constant RaycastParams* P, int gid) {
  int4 n = P->light_grid;
  return (int3)(gid % n.x, (gid / n.x) % n.y, gid / (n.x * n.y));
}

// Length in mm of a step du in voxel coordinates.
inline float voxel_mm(__constant RaycastParams* P, float3 du) {
  float3 w =
      (float3)(dot(P->to_world_x.xyz, du), dot(P->to_world_y.xyz, du), dot(P->to_world_z.xyz, du));
  return length(w);
}

__kernel void light_sigma(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                          __global float* sigma, int points) {
  int gid = get_global_id(0);
  if (gid >= points) return;
  float cell = (float)P->light_grid.w;
  int sub = min(P->light_grid.w, 4);  // sub-samples per axis
  float spacing = cell / (float)sub;
  float3 base = convert_float3(grid_point(P, gid)) * cell - 0.5f * cell + 0.5f * spacing;
  float3 hi = convert_float3(P->dims.xyz - 1);
  float sum = 0.0f;
  for (int z = 0; z < sub; ++z)
    for (int y = 0; y < sub; ++y)
      for (int x = 0; x < sub; ++x) {
        float3 p = clamp(base + (float3)(x, y, z) * spacing, (float3)(0.0f), hi);
        float a = clamp(lut_lookup(lut, P, sample_volume(VOLUME, P, p)).w, 0.0f, 0.999999f);
        sum += -log(1.0f - a);
      }
  sigma[gid] = sum / ((float)(sub * sub * sub) * P->view.w);
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
  float3 p = convert_float3(grid_point(P, gid)) * (float)P->light_grid.w;
  float3 du = P->light_v.xyz - p;
  // Scaled first: a light far away (at "infinity") must not overflow the length.
  float m = fmax(fabs(du.x), fmax(fabs(du.y), fabs(du.z)));
  float t = 1.0f;
  if (m > 1e-6f && isfinite(m)) {
    float len = voxel_mm(P, du / m);
    if (len > 0.0f) t = grid_transmittance(P, sigma, p, du / (m * len), P->light_march.w, m * len);
  }
  out[gid] = t;
}

__kernel void light_ao(__constant RaycastParams* P, __global const float* sigma,
                       __global float* out, int points) {
  int gid = get_global_id(0);
  if (gid >= points) return;
  float3 p = convert_float3(grid_point(P, gid)) * (float)P->light_grid.w;
  float sum = 0.0f;
  for (int i = 0; i < AO_DIRECTIONS; ++i) {
    float z = 1.0f - (2.0f * (float)i + 1.0f) / (float)AO_DIRECTIONS;
    float r = sqrt(fmax(0.0f, 1.0f - z * z)), phi = 2.39996323f * (float)i;
    float3 w = (float3)(r * cos(phi), r * sin(phi), z);
    // world direction -> voxels per mm: the rows of gradToWorld are worldToVoxel's columns
    float3 dv = w.x * P->grad_x.xyz + w.y * P->grad_y.xyz + w.z * P->grad_z.xyz;
    sum += grid_transmittance(P, sigma, p, dv, 0.0f, P->light_march.x);
  }
  out[gid] = sum / (float)AO_DIRECTIONS;
}
