// The raycaster: one work-item per pixel. Compiled per frame variant with -D options:
//   MODE 0 iso (first hit of a HU range, refined by bisection, shaded)
//        1 dvr (front-to-back emission-absorption, the seed's transparency formula)
//        2 mip
//   SHADING 0/1, GRADIENT 0..2, INTERP 0/1, STORAGE_IMAGE 0/1, ORTHO 0/1,
//   REFINE_STEPS n, OPACITY_CORRECTION 0/1
// Only what the variant needs is compiled: MIP and unshaded frames take no gradient.
// engine/src/reference_renderer.cpp is the same algorithm in double precision.
#include "params.cl"
#include "math.cl"
#include "intersect.cl"
#include "sampling.cl"
#if SHADING
#include "gradients.cl"
#include "shading.cl"
#endif

inline float4 lut_lookup(__global const float4* lut, __constant RaycastParams* P, float v) {
  float last = (float)(P->dims.w - 1);
  float x = clamp((v - P->values.z) * P->values.w, 0.0f, last);
  float i = floor(x);
  int k = (int)i;
  int k1 = min(k + 1, P->dims.w - 1);
  return mix(lut[k], lut[k1], x - i);
}

#if SHADING
// Normal at p (voxel coordinates) in world space; not normalised.
inline float3 world_gradient(VOLUME_ARG, __constant RaycastParams* P, float3 p) {
  float3 g = volume_gradient(vol, P->dims, p);
  return mat_mul(P->grad_x, P->grad_y, P->grad_z, g);
}
#endif

__kernel void raycast(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                      __global uchar4* out) {
  int px = get_global_id(0), py = get_global_id(1);
  int width = P->image.x, height = P->image.y;
  if (px >= width || py >= height) return;

  float sx = (2.0f * (px + 0.5f) / width - 1.0f) * P->view.x * P->view.y;
  float sy = (1.0f - 2.0f * (py + 0.5f) / height) * P->view.x;
#if ORTHO
  float3 origin_w = P->eye_w.xyz + P->right_w.xyz * sx + P->up_w.xyz * sy;
  float3 dir_w = P->forward_w.xyz;
  float3 origin_v = P->eye_v.xyz + P->right_v.xyz * sx + P->up_v.xyz * sy;
  float3 dir_v = P->forward_v.xyz;
#else
  float3 origin_w = P->eye_w.xyz;
  float3 unnorm = P->forward_w.xyz + P->right_w.xyz * sx + P->up_w.xyz * sy;
  float inv_len = rsqrt(dot(unnorm, unnorm));
  float3 dir_w = unnorm * inv_len;
  float3 origin_v = P->eye_v.xyz;
  float3 dir_v = (P->forward_v.xyz + P->right_v.xyz * sx + P->up_v.xyz * sy) * inv_len;
#endif
  float3 view_w = -dir_w;
  float3 color = P->background.xyz;

  float t0, t1;
  int axis = intersect_box(origin_v, dir_v, P->clip_lo.xyz, P->clip_hi.xyz, &t0, &t1);
  if (axis > -2) {
    float step = P->view.z;
    float len = t1 - t0;
    // A bounded count: a NaN or absurd length must not hang the device.
    int n = (int)clamp(ceil(len / step), 0.0f, 16777216.0f);
#if MODE == 0
    float lo = P->values.x, hi = P->values.y;
    int hit = -1;
    float t_hit = 0.0f;
    for (int i = 0; i <= n; ++i) {
      float t = fmin(t0 + i * step, t1);
      float v = sample_volume(vol, P->dims, origin_v + t * dir_v);
      if (v >= lo && v <= hi) {
        hit = i;
        t_hit = t;
        break;
      }
    }
    if (hit >= 0) {
      if (hit > 0) {
        float a = fmin(t0 + (hit - 1) * step, t1), b = t_hit;
        for (int k = 0; k < REFINE_STEPS; ++k) {
          float m = 0.5f * (a + b);
          float v = sample_volume(vol, P->dims, origin_v + m * dir_v);
          if (v >= lo && v <= hi) b = m;
          else a = m;
        }
        t_hit = REFINE_STEPS > 0 ? 0.5f * (a + b) : b;
      }
      float3 p_v = origin_v + t_hit * dir_v;
      float4 c = lut_lookup(lut, P, sample_volume(vol, P->dims, p_v));
#if SHADING
      float3 n_w;
      if (hit == 0 && axis >= 0) {
        // The ray starts inside the surface at a clip face: shade the cut as a flat cap.
        float3 e = (float3)(axis == 0, axis == 1, axis == 2);
        n_w = mat_mul(P->grad_x, P->grad_y, P->grad_z, e);
      } else {
        n_w = world_gradient(vol, P, p_v);
      }
      color = shade(c.xyz, n_w, origin_w + t_hit * dir_w, view_w, P->light_w, P->light);
#else
      color = c.xyz;
#endif
    }
#elif MODE == 1
    float3 acc = (float3)(0.0f);
    float alpha = 0.0f;
    float ref_step = P->view.w;
    for (int i = 0; i < n; ++i) {
      // Midpoint of each segment; the last one may be shorter than a step.
      float seg = fmin(step, len - i * step);
      float t = t0 + i * step + 0.5f * seg;
      float3 p_v = origin_v + t * dir_v;
      float4 c = lut_lookup(lut, P, sample_volume(vol, P->dims, p_v));
      if (c.w <= 0.0f) continue;
#if OPACITY_CORRECTION
      float a = 1.0f - pow(1.0f - c.w, seg / ref_step);
#else
      float a = c.w;
#endif
#if SHADING
      float3 rgb = shade(c.xyz, world_gradient(vol, P, p_v), origin_w + t * dir_w, view_w,
                         P->light_w, P->light);
#else
      float3 rgb = c.xyz;
#endif
      acc += (1.0f - alpha) * a * rgb;
      alpha += (1.0f - alpha) * a;
      if (alpha >= P->dvr.z) break;
    }
    color = acc + (1.0f - alpha) * P->background.xyz;
#else
    float vmax = -INFINITY;
    for (int i = 0; i <= n; ++i) {
      float t = fmin(t0 + i * step, t1);
      vmax = fmax(vmax, sample_volume(vol, P->dims, origin_v + t * dir_v));
    }
    float g = clamp((vmax - P->dvr.x) * P->dvr.y, 0.0f, 1.0f);
    color = (float3)(g);
#endif
  }
  color = clamp(color, 0.0f, 1.0f);
  out[py * width + px] = (uchar4)(convert_uchar3_sat_rte(color * 255.0f), 255);
}
