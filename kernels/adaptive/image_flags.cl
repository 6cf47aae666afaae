// Image-space adaptive sampling's two small kernels between and after the raycast passes
// (adaptive/image_pass.cl says the order). Compiled on their own: no switches, no volume.
#ifndef VOXRAY_IMAGE_FLAGS_CL
#define VOXRAY_IMAGE_FLAGS_CL

#include "adaptive/image_blocks.cl"

// The corners of block (bx, by): columns x0, x1 and rows y0, y1 of the lattice.
inline int4 image_corners(int4 ip, int2 size, int bx, int by) {
  int x0 = bx * ip.x, y0 = by * ip.x;
  return (int4)(x0, min(x0 + ip.x, size.x - 1), y0, min(y0 + ip.x, size.y - 1));
}

// iso (depth 1): whether the corners' hits (voxel coordinates, w < 0: none) show an edge the
// colours may not: some corners hit and others miss, or two neighbours lie more than 4 times
// farther apart in depth (from the eye; along `forward` when ortho) than across (a surface
// steeper than 76 degrees to the view, or a step between two surfaces), plus a voxel of slack.
inline bool depth_edge(__global const float4* hits, int2 size, int4 c, float4 eye, float4 forward,
                       int ortho) {
  float4 h[4] = {hits[c.z * size.x + c.x], hits[c.z * size.x + c.y], hits[c.w * size.x + c.y],
                 hits[c.w * size.x + c.x]};  // around the block
  int hit = 0;
  for (int i = 0; i < 4; ++i) hit += h[i].w >= 0.0f;
  if (hit == 0) return false;
  if (hit < 4) return true;
  float depth[4];
  for (int i = 0; i < 4; ++i)
    depth[i] =
        ortho ? dot(h[i].xyz - eye.xyz, normalize(forward.xyz)) : distance(h[i].xyz, eye.xyz);
  for (int i = 0; i < 4; ++i) {
    int j = (i + 1) & 3;
    float dz = fabs(depth[i] - depth[j]);
    float3 d = h[i].xyz - h[j].xyz;
    float across = sqrt(fmax(dot(d, d) - dz * dz, 0.0f));
    if (dz > 4.0f * across + 1.0f) return true;
  }
  return false;
}

// One work-item per block: refined (1) where its four lattice pixels differ by `threshold`
// levels or more in a channel (0: every block), or, with `depth` (iso), where depth_edge says.
// The error estimate is the corners' spread: bilinear fill is exact where they agree and the
// image is smooth in between; a hit or miss against the background shows as a jump of most of
// the range, one surface before another of the same colour only in depth.
__kernel void image_flags(__global const uchar4* out, __global uchar* flags, int4 ip, int2 size,
                          float threshold, __global const float4* hits, int depth, float4 eye,
                          float4 forward, int ortho) {
  int bx = get_global_id(0), by = get_global_id(1);
  int bw = max(ip.y - 1, 1), bh = max(ip.z - 1, 1);
  if (bx >= bw || by >= bh) return;
  int4 c = image_corners(ip, size, bx, by);
  int4 a = convert_int4(out[c.z * size.x + c.x]), b = convert_int4(out[c.z * size.x + c.y]);
  int4 d = convert_int4(out[c.w * size.x + c.x]), e = convert_int4(out[c.w * size.x + c.y]);
  int4 spread = max(max(a, b), max(d, e)) - min(min(a, b), min(d, e));
  int most = max(max(spread.x, spread.y), max(spread.z, spread.w));
  bool edge = (float)most >= threshold || (depth && depth_edge(hits, size, c, eye, forward, ortho));
  flags[by * bw + bx] = edge ? 1 : 0;
}

// One work-item per block (a pixel a work-item cost PoCL 5 ms at 512x384, about 10 % of an
// adaptive frame): each pixel it owns that is neither on the lattice nor marched by the refine
// pass (whose work-items cover `foot` pixels: 1 x 1, or a packet's 4 x rows; every pixel of
// a refined block is in one) is bilinear between the block's corners, rounded to the nearest
// level. A block owns its pixels up to the next block's corners; the last, the image's edge.
__kernel void image_fill(__global uchar4* out, __global const uchar* flags, int4 ip, int2 size,
                         int2 foot) {
  int bx = get_global_id(0), by = get_global_id(1);
  int bw = max(ip.y - 1, 1), bh = max(ip.z - 1, 1);
  if (bx >= bw || by >= bh || flags[by * bw + bx]) return;
  int4 c = image_corners(ip, size, bx, by);
  float4 a = convert_float4(out[c.z * size.x + c.x]), b = convert_float4(out[c.z * size.x + c.y]);
  float4 d = convert_float4(out[c.w * size.x + c.x]), e = convert_float4(out[c.w * size.x + c.y]);
  float iu = c.y > c.x ? 1.0f / (float)(c.y - c.x) : 0.0f;
  float iv = c.w > c.z ? 1.0f / (float)(c.w - c.z) : 0.0f;
  int xe = bx == bw - 1 ? size.x - 1 : c.y - 1, ye = by == bh - 1 ? size.y - 1 : c.w - 1;
  // A refine work-item lies in one block where its footprint divides K: then no pixel of an
  // unrefined block was marched, and the per-pixel test (25 ms of a 1024x768 frame on PoCL,
  // its integer divisions) is left out.
  bool straddles = ip.x % foot.x != 0 || ip.x % foot.y != 0;
  for (int y = c.z; y <= ye; ++y) {
    bool ly = y == c.z || y == size.y - 1;  // the lattice rows this block owns
    int fy = y / foot.y * foot.y;
    float v = (float)(y - c.z) * iv;
    for (int x = c.x; x <= xe; ++x) {
      if (ly && (x == c.x || x == size.x - 1)) continue;  // a lattice pixel
      if (straddles) {
        int fx = x / foot.x * foot.x;
        if (image_refined(flags, ip, fx, fy, min(fx + foot.x, size.x) - 1,
                          min(fy + foot.y, size.y) - 1))
          continue;  // marched with a refined block's packet
      }
      float u = (float)(x - c.x) * iu;
      float4 top = a + (b - a) * u, bottom = d + (e - d) * u;
      out[y * size.x + x] = convert_uchar4_sat_rte(top + (bottom - top) * v);
    }
  }
}

#endif
