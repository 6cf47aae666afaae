// The raycaster: one work-item per pixel, or per packet of rays on CPUs (PACKET,
// march/*_packet.cl). Compiled per frame variant with the -D switches of switches.h, which says
// what each one does. Only what the variant needs is compiled: MIP and unshaded frames take
// no gradient. engine/src/reference_renderer.cpp is the same algorithm in double precision.
//
// JITTER 1 (RenderParams.jitter) shifts each ray's samples forward by j steps, j in [0, 1)
// a hash of the pixel (jitter_hash.h, shared with the C++ reference renderer),
// with n = ceil((t1 - t0) / step) as without jitter:
//   iso, mip: sample i = 0..n at t_i = min(t0 + (i + j) * step, t1); the last is at t1.
//             An iso hit at i > 0 is refined between t_(i-1) and t_i; at i = 0 it is not.
//   dvr:      segment i = 0..n spans [max(t0, t0 + (i - 1 + j) * step),
//             min(t1, t0 + (i + j) * step)]; empty segments are skipped; each is sampled at
//             its midpoint and its opacity corrected for its length. Segment 0 is the
//             j * step stub before the first full step; with j = 0 it is empty and this is
//             exactly the unjittered march.
#include "intersection/ray.cl"
#include "march/march.cl"
#include "variant.cl"
// After the scalar files: what only packets use is compiled only with PACKET.
#if PACKET
#include "march/dvr_packet.cl"
#include "march/iso_packet.cl"
#include "march/mip_packet.cl"
#endif

// LABELS (dvr): the label map and the segment table follow the other arguments (LABEL_PARAMS,
// classification/labels.cl); then OVERLAY's (overlay.cl) and SURFACES' layer (surfaces.cl).
// count: COUNT_SAMPLES adds each ray's samples to one of 64 counters (fewer collisions
// than one; the host sums them). Unused otherwise, like leap and range without ESS.
// PACKET 1 (CPUs): each work-item marches the 4 x PACKET_ROWS pixels at (4 x, PACKET_ROWS y)
// together in SIMD (march/*_packet.cl); otherwise one work-item per pixel.
__kernel void raycast(VOLUME_ARG, __constant RaycastParams* P, __global const float4* lut,
                      __global uchar4* out, CELL_ARGS, __global uint* count
#if HIT_OUTPUT
                      ,
                      __global float4* hits
#endif
                          LABEL_PARAMS OVERLAY_PARAMS SURFACE_PARAMS IMAGE_PASS_PARAMS) {
#if IMAGE_PASS == 2
  {  // the refine pass (adaptive/image_pass.cl): only work-items that touch a refined block
#if PACKET
    int fw = 4, fh = MIP_HALVES * PACKET_ROWS;
#else
    int fw = 1, fh = 1;
#endif
    int x0 = fw * (int)get_global_id(0), y0 = fh * (int)get_global_id(1);
    if (x0 >= P->image.x || y0 >= P->image.y ||
        !image_refined(refine, P->image_pass, x0, y0, min(x0 + fw, P->image.x) - 1,
                       min(y0 + fh, P->image.y) - 1))
      return;
  }
#endif
#if PACKET
  if (MODE == 0)
    iso_packet(vol, P, lut, out, leap, range, count, get_global_id(0),
               get_global_id(1) PACKET_HITS_ARG LABEL_PASS OVERLAY_PASS SURFACE_PASS);
  else if (MODE == 1)
    dvr_packet(vol, P, lut, out, leap, range, count, get_global_id(0),
               get_global_id(1) PACKET_HITS_ARG LABEL_PASS OVERLAY_PASS SURFACE_PASS);
  else {
    mip_packet(vol, P, out, leap, range, count, get_global_id(0), get_global_id(1));
#if OVERLAY
    // Fused mip: each of the packets' pixels (pixel_raysN's layout) takes the overlay over
    // its grey, one ray at a time (overlay_mip).
    for (int y = 0; y < MIP_HALVES * PACKET_ROWS; ++y)
      for (int x = 0; x < 4; ++x) {
        int px = 4 * (int)get_global_id(0) + x,
            py = MIP_HALVES * PACKET_ROWS * (int)get_global_id(1) + y;
        Ray r;
        float3 ow, dw;
        if (px >= P->image.x || py >= P->image.y || pixel_ray(P, px, py, &r, &ow, &dw) <= -2)
          continue;
        __global uchar4* o = &out[py * P->image.x + px];
        *o = to_rgba8(
            overlay_mip(ovol, olut, ocells, ogeo, P, &r, convert_float3((*o).xyz) / 255.0f));
      }
#endif
  }
#if HIT_OUTPUT
  if (MODE == 2)  // no pixel of a mip frame has a hit
    for (int h = 0; h < MIP_HALVES; ++h)
      write_hits_packet(P, hits, get_global_id(0), MIP_HALVES * get_global_id(1) + h, 0.0f, 0.0f,
                        0.0f, -1.0f);
#endif
#else
  int px = get_global_id(0), py = get_global_id(1);
  IMAGE_PASS_PIXEL(int, px, py);  // the lattice pass: work-items on lattice pixels
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
      color = march_dvr(VOLUME, P, lut, leap, range, &r, origin_w, dir_w, &samples
#if HIT_OUTPUT
                        ,
                        &hit
#endif
                            LABEL_PASS OVERLAY_PASS SURFACE_PASS);
    else {
      color = march_mip(VOLUME, P, leap, range, &r, &samples);
#if OVERLAY
      color = overlay_mip(ovol, olut, ocells, ogeo, P, &r, color);
#endif
    }
  }
  out[py * width + px] = to_rgba8(color);
  if (COUNT_SAMPLES) atomic_add(&count[(px ^ py) & 63], samples);
#if HIT_OUTPUT
  hits[py * width + px] = hit;
#endif
#endif
}
