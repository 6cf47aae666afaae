// The progressive path tracer (lighting `cinematic`, issue 15): one path per work-item and
// sample, added to a float accumulation buffer that persists across calls, so N samples
// give the same sum however they were split into passes. engine/src/path_reference.cpp is
// the same estimator in double precision; engine/include/voxray/engine/path_tracer.h says
// what it models:
//   extinction  sigma(x) = -ln(1 - min(a(x), cap)) / ref_step per mm, a(x) the transfer
//               function's opacity, which is defined per reference step (the smallest voxel
//               spacing, as opacity correction reads it); cap < 1 keeps sigma finite.
//   albedo      the transfer function's colour; no emission.
//   phase       isotropic (1 / 4 pi).
//   tracking    delta (Woodcock) tracking against a piecewise-constant majorant: one per
//               cell of PT_CELL^3 voxels (engine/src/path_majorants.h), walked cell by cell
//               (a flight that leaves its cell restarts at the boundary: exponential flights
//               are memoryless), so empty cells cost one step; ratio tracking with Russian
//               roulette for the transmittance of next-event rays to the point light.
//   lights      the point light (no falloff: a light at 1e30 mm is a directional light)
//               with irradiance 4 pi diffuse, so an unshadowed scatter of albedo c returns
//               c diffuse; a uniform environment of radiance `ambient` reached by paths
//               that leave the clip box after a scatter. A camera ray that leaves without
//               scattering shows the background colour.
//   bounces     at most MAX_BOUNCES scatters per path (counters.w), no roulette.
// The same -D switches as raycast.cl (sampling and ray setup); MODE is dvr.
#include "classification/lut.cl"
#include "intersection/ray.cl"
#include "math.cl"
#include "path_rng.h"
#include "reconstruction/sampling.cl"
#include "shading/shading.cl"

#define PT_MAX_STEPS 1048576  // tentative collisions per segment: a bound, never reached
#define PT_CELL 8             // voxels per majorant cell edge (path_majorants.h: kPathCell)

typedef struct {
  voxray_u32 key;
  voxray_u32 i;
} PathRng;

inline float pt_uniform(PathRng* r) {
  return (float)voxray_path_bits(r->key, r->i++) * (float)VOXRAY_PATH_UNIT;
}

// A free-flight distance against the majorant; 1 - u is in (0, 1].
inline float pt_free_path(PathRng* r, float majorant) {
  return -log(1.0f - pt_uniform(r)) / majorant;
}

inline float pt_sigma(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                      float4 lights, float3 p_v, float3* albedo) {
  float4 c = lut_lookup(lut, P, sample_volume(VOLUME, P, p_v));
  *albedo = c.xyz;
  return -log(1.0f - clamp(c.w, 0.0f, lights.w)) / P->view.w;
}

// Uniform on the unit sphere.
inline float3 pt_direction(PathRng* r) {
  float z = 1.0f - 2.0f * pt_uniform(r);
  float phi = 6.28318530717958647692f * pt_uniform(r);
  float s = sqrt(fmax(0.0f, 1.0f - z * z));
  return (float3)(s * cos(phi), s * sin(phi), z);
}

inline float3 pt_to_voxel(float4 mx, float4 my, float4 mz, float3 w) {
  return (float3)(dot(mx.xyz, w), dot(my.xyz, w), dot(mz.xyz, w));
}

// Where a ray from p_v (inside the clip box) along d_v leaves it, in mm.
inline float pt_exit(__constant RaycastParams* P, float3 p_v, float3 d_v) {
  float t0, t1;
  if (intersect_box(p_v, d_v, P->clip_lo.xyz, P->clip_hi.xyz, &t0, &t1) < -1) return 0.0f;
  return fmax(t1, 0.0f);
}

// The majorant of the cell holding o + t d (voxel coordinates, d per mm) into *sigma_max,
// and where the ray leaves that cell (mm), at least a hair beyond t so a point on a face
// moves on.
inline float pt_cell(__global const float* majorants, int4 grid, float3 o, float3 d, float t,
                     float* sigma_max) {
  float3 p = o + t * d;
  int3 c = clamp(convert_int3(floor((p + 0.5f) / PT_CELL)), (int3)(0), grid.xyz - 1);
  *sigma_max = majorants[(c.z * grid.y + c.y) * grid.x + c.x];
  float3 lo = convert_float3(c * PT_CELL) - 0.5f;
  float3 far = select(lo + PT_CELL, lo, isless(d, 0.0f));
  float3 tf = select((far - o) / d, (float3)(INFINITY), isequal(d, 0.0f));
  return fmax(fmin(tf.x, fmin(tf.y, tf.z)), t + 1e-5f * (1.0f + fabs(t)));
}

// Transmittance from p_v over t_max mm along d_v: ratio tracking, Russian roulette below 0.1.
// Moves *t on to the next tentative collision before t_end, cell by cell, and gives its
// cell's majorant (true); or to t_end when there is none (false).
inline bool pt_flight(__global const float* majorants, int4 grid, float3 o, float3 d, float t_end,
                      PathRng* rng, float* t, float* sigma_max) {
  for (int k = 0; k < PT_MAX_STEPS && *t < t_end; ++k) {
    float tb = fmin(pt_cell(majorants, grid, o, d, *t, sigma_max), t_end);
    float tn = *sigma_max > 0.0f ? *t + pt_free_path(rng, *sigma_max) : tb;
    if (tn < tb) {
      *t = tn;
      return true;
    }
    *t = tb;
  }
  return false;
}

inline float pt_transmittance(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                              __global const float* majorants, int4 grid, float4 lights, float3 p_v,
                              float3 d_v, float t_max, PathRng* rng) {
  float tr = 1.0f, t = 0.0f, sigma_max;
  float3 albedo;
  for (int k = 0; k < PT_MAX_STEPS && tr > 0.0f &&
                  pt_flight(majorants, grid, p_v, d_v, t_max, rng, &t, &sigma_max);
       ++k) {
    float sigma = pt_sigma(VOLUME, P, lut, lights, p_v + t * d_v, &albedo);
    tr *= fmax(0.0f, 1.0f - sigma / sigma_max);
    if (tr < 0.1f) tr = pt_uniform(rng) < 0.5f ? 0.0f : 2.0f * tr;
  }
  return tr;
}

// One path's radiance for pixel (px, py).
inline float3 pt_path(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                      __global const float* majorants, int4 grid, float4 mx, float4 my, float4 mz,
                      float4 lights, int max_bounces, int px, int py, PathRng* rng) {
  float3 o_w, d_w;
  Ray r;
  if (pixel_ray(P, px, py, &r, &o_w, &d_w) < -1) return P->background.xyz;
  float3 o_v = r.o, d_v = r.d;
  float t0 = r.t0, t1 = r.t1;
  float majorant = lights.z;
  float3 beta = (float3)(1.0f), radiance = (float3)(0.0f);
  for (int bounce = 0;; ++bounce) {
    // Delta tracking over [t0, t1): a real collision with probability sigma / majorant.
    float t = t0;
    bool collided = false;
    float3 albedo = (float3)(0.0f);
    float sigma_max;
    for (int k = 0; k < PT_MAX_STEPS && majorant > 0.0f &&
                    pt_flight(majorants, grid, o_v, d_v, t1, rng, &t, &sigma_max);
         ++k) {
      float sigma = pt_sigma(VOLUME, P, lut, lights, o_v + t * d_v, &albedo);
      if (pt_uniform(rng) * sigma_max < sigma) {
        collided = true;
        break;
      }
    }
    if (!collided) {
      radiance += beta * (bounce == 0 ? P->background.xyz : (float3)(lights.y));
      break;
    }
    if (bounce == max_bounces) break;
    float3 x_w = o_w + t * d_w, x_v = o_v + t * d_v;
    beta *= albedo;
    if (!(fmax(beta.x, fmax(beta.y, beta.z)) > 0.0f)) break;
    // Next event: the point light, unshadowed but for the volume up to it or the box's edge.
    float3 to_light = P->light_w.xyz - x_w;
    float3 l_w = safe_normalize(to_light, -d_w);
    float3 l_v = pt_to_voxel(mx, my, mz, l_w);
    float dist = dot(to_light, l_w);  // finite: light_w is a float
    float reach = fmin(pt_exit(P, x_v, l_v), fmax(dist, 0.0f));
    radiance += beta * lights.x *
                pt_transmittance(VOLUME, P, lut, majorants, grid, lights, x_v, l_v, reach, rng);
    // Scatter: a new direction from the isotropic phase function, its weight 1.
    d_w = pt_direction(rng);
    d_v = pt_to_voxel(mx, my, mz, d_w);
    o_w = x_w;
    o_v = x_v;
    t0 = 0.0f;
    t1 = pt_exit(P, x_v, d_v);
  }
  return radiance;
}

// counters: x seed, y index of this pass's first sample, z samples this pass, w max bounces.
// mx, my, mz: rows of the world-to-voxel matrix (directions only). lights: x point light
// (diffuse), y environment radiance (ambient), z the largest majorant (per mm; 0: nothing
// to collide with), w opacity cap. majorants: per cell of the grid (x, y, z cells).
// accum holds the radiance summed over samples 0 .. y - 1 (xyz); out gets the mean.
__kernel void path_trace(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                         __global float4* accum, __global uchar4* out,
                         __global const float* majorants, int4 grid, float4 mx, float4 my,
                         float4 mz, float4 lights, uint4 counters) {
  int px = get_global_id(0), py = get_global_id(1);
  int width = P->image.x, height = P->image.y;
  if (px >= width || py >= height) return;
  int pixel = py * width + px;
  float3 sum = counters.y == 0 ? (float3)(0.0f) : accum[pixel].xyz;
  for (uint s = 0; s < counters.z; ++s) {
    PathRng rng = {voxray_path_key(counters.x, (uint)pixel, counters.y + s), 0u};
    sum +=
        pt_path(VOLUME, P, lut, majorants, grid, mx, my, mz, lights, (int)counters.w, px, py, &rng);
  }
  accum[pixel] = (float4)(sum, 0.0f);
  float n = (float)(counters.y + counters.z);
  out[pixel] = to_rgba8(sum / fmax(n, 1.0f));
}
