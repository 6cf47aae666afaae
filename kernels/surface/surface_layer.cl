// The surface pass (issue 34): before a dvr frame with segments shown as surfaces, one
// work-item per pixel finds where its ray first crosses the 0.5 level of each surface's
// smoothed occupancy field (engine/src/surface_field.h), refines the crossing by bisection,
// shades it (Blinn-Phong, the frame's light) with the normal from the field's gradient and
// the segment's colour, and composites the hits front to back into the pixel's layer
// (surface_layer.h). The dvr march (march.cl, dvr_packet.cl: SURFACES) then inserts that layer
// at the nearest hit's depth, so the volume in front of a surface covers it, and the volume
// behind a semi-transparent one shows through.
//
// Why a pre-pass and one layer, not the fields sampled inside the dvr march: the march's
// samples (and the CPU packets' SIMD loop) stay as they are, paying one depth compare per
// sample; the surfaces get their own empty-space skipping (block flags) and a finer search
// than the dvr step would give. The cost: surfaces behind the nearest one are inserted at its
// depth (the dvr between two surfaces of one pixel composites behind both).
//
// Compiled with the frame's ORTHO (pixel_ray) and SURFACE_PROBE: 1 also writes each pixel's
// nearest hit (world point, label; outward unit normal) for the tests.
#include "intersection/ray.cl"
#include "math.cl"
#include "shading/shading.cl"
#include "surface_layer.h"

#define SURFACE_REFINE 10  // bisection steps: the step / 1024, far below a pixel

// The field's value 0 ... 1 at q (its own voxel coordinates), trilinear; 0 outside its box.
inline float field_at(__global const uchar* restrict f, int4 g0, int4 g1, float3 q) {
  float3 last = convert_float3(g1.xyz - 1);
  if (any(q < 0.0f) || any(q > last)) return 0.0f;
  float3 fl = floor(q);
  int3 i = convert_int3(fl);
  int3 j = min(i + 1, g1.xyz - 1);
  float3 w = q - fl;
  const int sy = g1.x, sz = g1.x * g1.y;
  __global const uchar* b = f + g0.w;
#define FV(x, y, z) (float)b[(z)*sz + (y)*sy + (x)]
  float c00 = mix(FV(i.x, i.y, i.z), FV(j.x, i.y, i.z), w.x);
  float c10 = mix(FV(i.x, j.y, i.z), FV(j.x, j.y, i.z), w.x);
  float c01 = mix(FV(i.x, i.y, j.z), FV(j.x, i.y, j.z), w.x);
  float c11 = mix(FV(i.x, j.y, j.z), FV(j.x, j.y, j.z), w.x);
#undef FV
  return mix(mix(c00, c10, w.y), mix(c01, c11, w.y), w.z) * (1.0f / 255.0f);
}

// Whether the block holding q (field coordinates, inside the box) may hold the 0.5 level.
inline bool block_may_hit(__global const uchar* restrict f, int4 g1, int4 g2, float3 q) {
  int3 b = clamp(convert_int3(q) / SURFACE_BLOCK, (int3)(0), g2.xyz - 1);
  return f[g1.w + (b.z * g2.y + b.y) * g2.x + b.x] != 0;
}

// Ray depth where the ray at q (field coordinates, depth t) leaves q's block.
inline float block_exit(const Ray* r, float3 q, float t) {
  float3 b = floor(q / SURFACE_BLOCK) * SURFACE_BLOCK;
  float3 far = select(b, b + SURFACE_BLOCK, isgreater(r->d, 0.0f));
  float3 dt = (far - q) * r->inv_d;  // inv_d 0 along an axis the ray does not move on
  dt = select(dt, (float3)(SURFACE_NONE), isequal(r->inv_d, 0.0f) | isless(dt, 0.0f));
  return t + fmin(dt.x, fmin(dt.y, dt.z)) + 1e-3f;
}

// The first depth in [ta, tb] where surface s's field reaches 0.5, refined; -1: none.
inline float surface_hit(__global const uchar* restrict f, int4 g0, int4 g1, int4 g2, const Ray* r,
                         float ta, float tb) {
  float3 lo = convert_float3(g0.xyz);
  float prev = ta, t = ta;
  bool first = true;
  for (int guard = 0; t <= tb && guard < 65536; ++guard) {
    float3 q = r->o + t * r->d - lo;
    if (!block_may_hit(f, g1, g2, q)) {  // the block's values stay below 0.5: leap it
      prev = t = block_exit(r, q, t);
      first = false;
      continue;
    }
    if (field_at(f, g0, g1, q) >= 0.5f) {
      if (first) return t;  // the ray starts inside (a clip face): no crossing to refine
      float a = prev, b = t;
      for (int k = 0; k < SURFACE_REFINE; ++k) {
        float m = 0.5f * (a + b);
        if (field_at(f, g0, g1, r->o + m * r->d - lo) >= 0.5f)
          b = m;
        else
          a = m;
      }
      return 0.5f * (a + b);
    }
    first = false;
    prev = t;
    t = t < tb ? fmin(t + r->step, tb) : tb + 1.0f;  // the last sample at tb
  }
  return -1.0f;
}

__kernel void surface_layer(__constant RaycastParams* P, __global const uchar* restrict fields,
                            __constant int4* geo, __constant float4* colours, int count,
                            __global float4* layer
#if SURFACE_PROBE
                            ,
                            __global float4* probe
#endif
) {
  int px = get_global_id(0), py = get_global_id(1);
  if (px >= P->image.x || py >= P->image.y) return;
  size_t pix = (size_t)py * P->image.x + px;
  float3 origin_w, dir_w;
  Ray r;
  float ts[SURFACE_MAX];
  float4 cs[SURFACE_MAX];
  int found = 0, nearest_label = 0;
  float3 nearest_n = (float3)(0.0f), nearest_p = (float3)(0.0f);
  if (pixel_ray(P, px, py, &r, &origin_w, &dir_w) > -2 && r.t1 > r.t0) {
    for (int s = 0; s < count && s < SURFACE_MAX; ++s) {
      int4 g0 = geo[3 * s], g1 = geo[3 * s + 1], g2 = geo[3 * s + 2];
      float ta, tb;
      float3 lo = convert_float3(g0.xyz), hi = convert_float3(g0.xyz + g1.xyz - 1);
      if (intersect_box(r.o, r.d, lo, hi, &ta, &tb) < -1) continue;
      ta = fmax(ta, r.t0);
      tb = fmin(tb, r.t1);
      if (ta > tb) continue;
      float t = surface_hit(fields, g0, g1, g2, &r, ta, tb);
      if (t < 0.0f) continue;
      // The normal: the field's central differences (voxel coordinates) to world space; the
      // field grows inward, so the outward normal is minus its gradient.
      float3 q = r.o + t * r.d - lo;
      float3 g = (float3)(field_at(fields, g0, g1, q + (float3)(1.0f, 0.0f, 0.0f)) -
                              field_at(fields, g0, g1, q - (float3)(1.0f, 0.0f, 0.0f)),
                          field_at(fields, g0, g1, q + (float3)(0.0f, 1.0f, 0.0f)) -
                              field_at(fields, g0, g1, q - (float3)(0.0f, 1.0f, 0.0f)),
                          field_at(fields, g0, g1, q + (float3)(0.0f, 0.0f, 1.0f)) -
                              field_at(fields, g0, g1, q - (float3)(0.0f, 0.0f, 1.0f)));
      float3 n_w = -mat_mul(P->grad_x, P->grad_y, P->grad_z, g);
      float3 pos_w = origin_w + t * dir_w;
      float4 col = colours[s];
      float3 rgb = shade(col.xyz, n_w, pos_w, -dir_w, P->light_w, P->light);
      // Insert by depth (count is at most SURFACE_MAX).
      int k = found++;
      for (; k > 0 && ts[k - 1] > t; --k) ts[k] = ts[k - 1], cs[k] = cs[k - 1];
      ts[k] = t;
      cs[k] = (float4)(rgb, col.w);
      if (k == 0) {
        nearest_label = g2.w;
        nearest_p = pos_w;
        nearest_n = safe_normalize(n_w, -dir_w);
      }
    }
  }
  float3 acc = (float3)(0.0f);
  float alpha = 0.0f;
  for (int k = 0; k < found; ++k) {
    acc += (1.0f - alpha) * cs[k].w * cs[k].xyz;
    alpha += (1.0f - alpha) * cs[k].w;
  }
  layer[2 * pix] = (float4)(acc, alpha);
  layer[2 * pix + 1] = (float4)(found > 0 ? ts[0] : SURFACE_NONE, 0.0f, 0.0f, 0.0f);
#if SURFACE_PROBE
  probe[2 * pix] = (float4)(nearest_p, (float)nearest_label);
  probe[2 * pix + 1] = (float4)(nearest_n, 0.0f);
#endif
}
