// The raycaster: one work-item per pixel. Compiled per frame variant with -D options:
//   MODE 0 iso (first hit of a HU range, refined by bisection, shaded)
//        1 dvr (front-to-back emission-absorption, the seed's transparency formula)
//        2 mip
//   SHADING 0/1, GRADIENT 0..2, INTERP 0/1, STORAGE_IMAGE 0/1, ORTHO 0/1,
//   REFINE_STEPS n, OPACITY_CORRECTION 0/1, JITTER 0/1, ESS 0/1 (empty-space skipping,
//   skip.cl), COUNT_SAMPLES 0/1, UBER 0/1 (all switches at runtime: variant.cl),
//   PACKET 0/1 (CPUs: LANES = 8 or 16 rays per work-item in SIMD, packet.cl, lanes.cl),
//   HIT_OUTPUT 0/1 (iso, one ray per work-item: each pixel's hit to `hits`, see
//   march_iso; w -1 for none), SLABS k (the volume in k z slabs, slabs.cl; k > 1 only
//   without PACKET)
// Only what the variant needs is compiled: MIP and unshaded frames take no gradient.
// engine/src/reference_renderer.cpp is the same algorithm in double precision.
//
// JITTER 1 (RenderParams.jitter) shifts each ray's samples forward by j steps, j in [0, 1)
// a hash of the pixel (jitter_fraction below, bit-exact in C++ with uint32_t):
//   uint h = (uint)px * 73856093u ^ (uint)py * 19349663u;
//   h = (h ^ (h >> 13)) * 0x5bd1e995u;  h ^= h >> 15;
//   j = (float)(h & 0xffffffu) / 16777216.0f;
// with n = ceil((t1 - t0) / step) as without jitter:
//   iso, mip: sample i = 0..n at t_i = min(t0 + (i + j) * step, t1); the last is at t1.
//             An iso hit at i > 0 is refined between t_(i-1) and t_i; at i = 0 it is not.
//   dvr:      segment i = 0..n spans [max(t0, t0 + (i - 1 + j) * step),
//             min(t1, t0 + (i + j) * step)]; empty segments are skipped; each is sampled at
//             its midpoint and its opacity corrected for its length. Segment 0 is the
//             j * step stub before the first full step; with j = 0 it is empty and this is
//             exactly the unjittered march.
#include "intersect.cl"
#include "march.cl"
#include "ray.cl"
#include "variant.cl"

// Pixel (px, py)'s ray in voxel coordinates (r) and in world space (origin_w, dir_w),
// clipped to the clip box. Returns the clip box's entry axis (0..2), -1 when the eye is
// inside it, or -2 when the ray misses it (r is then incomplete).
inline int pixel_ray(__constant RaycastParams* P, int px, int py, Ray* r, float3* origin_w,
                     float3* dir_w) {
  int width = P->image.x, height = P->image.y;
  float sx = (2.0f * (px + 0.5f) / width - 1.0f) * P->view.x * P->view.y;
  float sy = (1.0f - 2.0f * (py + 0.5f) / height) * P->view.x;
  if (ORTHO) {
    *origin_w = P->eye_w.xyz + P->right_w.xyz * sx + P->up_w.xyz * sy;
    *dir_w = P->forward_w.xyz;
    r->o = P->eye_v.xyz + P->right_v.xyz * sx + P->up_v.xyz * sy;
    r->d = P->forward_v.xyz;
  } else {
    *origin_w = P->eye_w.xyz;
    float3 unnorm = P->forward_w.xyz + P->right_w.xyz * sx + P->up_w.xyz * sy;
    float inv_len = rsqrt(dot(unnorm, unnorm));
    *dir_w = unnorm * inv_len;
    r->o = P->eye_v.xyz;
    r->d = (P->forward_v.xyz + P->right_v.xyz * sx + P->up_v.xyz * sy) * inv_len;
  }
  int axis = intersect_box(r->o, r->d, P->clip_lo.xyz, P->clip_hi.xyz, &r->t0, &r->t1);
  if (axis > -2) {
    r->step = P->view.z;
    r->inv_d = select(1.0f / r->d, (float3)(0.0f), isequal(r->d, 0.0f));
    r->j = JITTER ? jitter_fraction(px, py) : 0.0f;
    // A bounded count: a NaN or absurd length must not hang the device.
    r->n = (int)clamp(ceil((r->t1 - r->t0) / r->step), 0.0f, 16777216.0f);
  }
  return axis;
}

inline uchar4 to_rgba8(float3 color) {
  return (uchar4)(convert_uchar3_sat_rte(clamp(color, 0.0f, 1.0f) * 255.0f), 255);
}

#if PACKET
#include "packet.cl"
#endif

// count: COUNT_SAMPLES adds each ray's samples to one of 64 counters (fewer collisions
// than one; the host sums them). Unused otherwise, like leap and range without ESS.
// PACKET 1 (CPUs): each work-item marches the 4 x PACKET_ROWS pixels at (4 x, PACKET_ROWS y)
// together in SIMD (packet.cl); otherwise one work-item per pixel.
__kernel void raycast(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                      __global uchar4* out, CELL_ARGS, __global uint* count
#if HIT_OUTPUT
                      ,
                      __global float4* hits
#endif
) {
#if PACKET
  if (MODE == 0)
    iso_packet(vol, P, lut, out, leap, range, count, get_global_id(0), get_global_id(1));
  else if (MODE == 1)
    dvr_packet(vol, P, lut, out, leap, range, count, get_global_id(0), get_global_id(1));
  else
    mip_packet(vol, P, out, leap, range, count, get_global_id(0), get_global_id(1));
#else
  int px = get_global_id(0), py = get_global_id(1);
  int width = P->image.x, height = P->image.y;
  if (px >= width || py >= height) return;
  float3 origin_w, dir_w;
  Ray r;
  float3 color = P->background.xyz;
  uint samples = 0;
  float4 hit = (float4)(0.0f, 0.0f, 0.0f, -1.0f);
  int axis = pixel_ray(P, px, py, &r, &origin_w, &dir_w);
  if (axis > -2) {
    if (MODE == 0)
      color = march_iso(VOLUME, P, lut, leap, range, &r, origin_w, dir_w, axis, &samples, &hit);
    else if (MODE == 1)
      color = march_dvr(VOLUME, P, lut, leap, range, &r, origin_w, dir_w, &samples);
    else
      color = march_mip(VOLUME, P, leap, range, &r, &samples);
  }
  out[py * width + px] = to_rgba8(color);
  if (COUNT_SAMPLES) atomic_add(&count[(px ^ py) & 63], samples);
#if HIT_OUTPUT
  hits[py * width + px] = hit;
#endif
#endif
}
