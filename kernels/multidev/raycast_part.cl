// One part of a sort-last frame over several devices (engine/src/multi_device.cpp, issue 38):
// this device holds only slices [part.x, part.x + part.y) of the volume (its z range and an
// apron, reconstruction/slabs.cl with VOXRAY_PART) and marches each pixel's ray over the
// samples (dvr: segments) of its range only.
//
// Every part makes the whole frame's ray (pixel_ray: the clip box's entry and exit, the step
// and the jitter of the one-device frame), so sample i lies where the one-device frame puts
// it. A part takes the indices from where the ray crosses the plane z = bounds.x to where it
// crosses z = bounds.y (voxel coordinates; ray_index_at). Neighbouring parts compute the plane
// they share with the same expression from the same ray, so every sample is taken by exactly
// one part. The rule is half-open along the ray: a sample on a boundary plane belongs to the
// part the ray enters there. open.x (open.y): there is no lower (upper) plane, the first
// (last) part takes everything below (above).
//
// Out per pixel, colour without the background, premultiplied, and `order` (the host
// composites by it, per pixel):
//   dvr: (acc, alpha) of the part's segments; order their first index, FLT_MAX when none
//   iso: the shaded first hit with alpha 1; order its index, FLT_MAX when none
//   mip: the window-mapped maximum of the part's samples, alpha 1 where the ray meets the
//        clip box (the one-device frame shows black there, the background elsewhere)
// PART_HALF (a part whose image the first device composites, composite_parts.cl): the colour
// in half floats (vstore_half4, round to nearest: relative error at most 2^-11) into `colour`
// as a half buffer, and no order (the slabs' order serves every pixel).
// Phong only, one ray per work-item (no packets), no labels, overlay or adaptive steps: the
// host asks for none of them.
#define VOXRAY_PART 1
#ifndef PART_HALF
#define PART_HALF 0
#endif
#include "intersection/ray.cl"
#include "march/march.cl"
#include "variant.cl"

// The first index at or beyond the ray's crossing of the plane z (r->d.z != 0).
inline int part_plane_index(const Ray* r, float z, bool segments) {
  return ray_index_at(r, (z - r->o.z) / r->d.z, segments);
}

// The indices [*i0, *i1) of r's samples (segments) between the part's planes.
inline void part_range(const Ray* r, float2 bounds, int2 open, bool segments, int* i0, int* i1) {
  int all = r->n + 1;
  if (r->d.z == 0.0f) {  // the ray stays in one plane z: one part takes it all
    bool in = (open.x || r->o.z >= bounds.x) && (open.y || r->o.z < bounds.y);
    *i0 = 0;
    *i1 = in ? all : 0;
    return;
  }
  bool up = r->d.z > 0.0f;
  int at_lo = open.x ? (up ? 0 : all) : part_plane_index(r, bounds.x, segments);
  int at_hi = open.y ? (up ? all : 0) : part_plane_index(r, bounds.y, segments);
  *i0 = up ? at_lo : at_hi;
  *i1 = up ? at_hi : at_lo;
}

// march_iso (march.cl) over indices [i0, i1): the first hit, refined between the sample
// before it (which may be the previous part's: the apron holds it) and the hit.
inline float3 part_iso(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                       CELL_ARGS, const Ray* r, float3 origin_w, float3 dir_w, int axis, int i0,
                       int i1, int* hit_index) {
  int hit = -1;
  float t_hit = 0.0f;
  for (int i = i0, check = i0; i < i1; ++i) {
    if (ESS && i >= check) {
      i = ess_leap(leap, range, P, r, false, i, &check);
      if (i >= i1) break;
    }
    float t = ray_sample_t(r, i);
    if (in_iso(P, sample_volume(VOLUME, P, r->o + t * r->d))) {
      hit = i;
      t_hit = t;
      break;
    }
  }
  *hit_index = hit;
  if (hit < 0) return (float3)(0.0f);
  if (hit > 0) {
    float a = ray_sample_t(r, hit - 1), b = t_hit;
    for (int k = 0; k < REFINE_STEPS; ++k) {
      float m = 0.5f * (a + b);
      if (in_iso(P, sample_volume(VOLUME, P, r->o + m * r->d)))
        b = m;
      else
        a = m;
    }
    t_hit = REFINE_STEPS > 0 ? 0.5f * (a + b) : b;
  }
  float3 p_v = r->o + t_hit * r->d;
  float4 c = lut_lookup(lut, P, sample_volume(VOLUME, P, p_v));
  if (!SHADING) return c.xyz;
  float3 n_w;
  if (hit == 0 && axis >= 0) {
    float3 e = (float3)(axis == 0, axis == 1, axis == 2);
    n_w = mat_mul(P->grad_x, P->grad_y, P->grad_z, e);
  } else {
    n_w = world_gradient(VOLUME, P, p_v);
  }
  return shade(c.xyz, n_w, origin_w + t_hit * dir_w, -dir_w, P->light_w, frame_light(lut, P, p_v));
}

// march_dvr (march.cl) over segments [i0, i1), without the background. The part stops at its
// own opacity P->dvr.z; the host stops compositing where the sum reaches it.
inline float4 part_dvr(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                       CELL_ARGS, const Ray* r, float3 origin_w, float3 dir_w, int i0, int i1) {
  float3 acc = (float3)(0.0f);
  float alpha = 0.0f;
  uint count = 0;
  for (int i = i0, check = i0; i < i1; ++i) {
    if (ESS && i >= check) {
      i = ess_leap(leap, range, P, r, true, i, &check);
      if (i >= i1) break;
    }
    if (dvr_segment(VOLUME, P, lut, r, ray_segment(r, i), origin_w, dir_w, &count, &acc,
                    &alpha LABEL_PASS OVERLAY_PASS))
      break;
  }
  return (float4)(acc, alpha);
}

// march_mip (march.cl) over samples [i0, i1).
inline float part_mip(VOLUME_ARG, __constant RaycastParams* P, CELL_ARGS, const Ray* r, int i0,
                      int i1) {
  float vmax = -FLT_MAX, low = P->dvr.x, high = P->dvr.x + 1.0f / P->dvr.y;
  for (int i = i0, check = i0; i < i1 && vmax < high; ++i) {
    if (ESS && i >= check) {
      i = ess_next_mip(range, P, r, i, fmax(vmax, low), &check);
      if (i >= i1) break;
    }
    vmax = fmax(vmax, sample_volume(VOLUME, P, r->o + ray_sample_t(r, i) * r->d));
  }
  return clamp((vmax - low) * P->dvr.y, 0.0f, 1.0f);
}

__kernel void raycast_part(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                           __global float4* colour, __global float* order, CELL_ARGS, float2 bounds,
                           int2 open) {
  int px = get_global_id(0), py = get_global_id(1);
  int width = P->image.x, height = P->image.y;
  if (px >= width || py >= height) return;
  float3 origin_w, dir_w;
  Ray r;
  float4 c = (float4)(0.0f);
  float o = FLT_MAX;
  int axis = pixel_ray(P, px, py, &r, &origin_w, &dir_w);
  if (axis > -2) {
    int i0, i1;
    part_range(&r, bounds, open, MODE == 1, &i0, &i1);
    if (MODE == 0) {
      int hit;
      float3 rgb = part_iso(VOLUME, P, lut, leap, range, &r, origin_w, dir_w, axis, i0, i1, &hit);
      if (hit >= 0) c = (float4)(rgb, 1.0f), o = (float)hit;
    } else if (MODE == 1) {
      if (i0 < i1) {
        c = part_dvr(VOLUME, P, lut, leap, range, &r, origin_w, dir_w, i0, i1);
        o = (float)i0;
      }
    } else {
      float g = part_mip(VOLUME, P, leap, range, &r, i0, i1);
      c = (float4)(g, g, g, 1.0f);
    }
  }
#if PART_HALF
  (void)o;
  (void)order;
  vstore_half4(c, (size_t)py * width + px, (__global half*)colour);
#else
  colour[py * width + px] = c;
  order[py * width + px] = o;
#endif
}
