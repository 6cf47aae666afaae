// hit_output.cl for packets (march_lanes.cl): the dvr crossing lane by lane, and the
// packet's pixels written to raycast.cl's hits.
#ifndef VOXRAY_HIT_OUTPUT_LANES_CL
#define VOXRAY_HIT_OUTPUT_LANES_CL

#include "march/hit_output.cl"
#include "simd/lanes.cl"

// dvr_hit_crossing for the lanes whose segment [ta, tb] crosses DVR_HIT_ALPHA: their *t_hit,
// and *found.
inline void dvr_hit_crossingN(floatN before, floatN after, floatN ta, floatN tb, floatN* t_hit,
                              intN* found) {
  intN cross = (before < DVR_HIT_ALPHA) & (after >= DVR_HIT_ALPHA);
  if (!any(cross)) return;
  // Lanes that do not cross may divide by zero: their result is dropped.
  *t_hit = select(*t_hit, DVR_HIT_T(before, after, ta, tb), cross);
  *found |= cross;
}

// The packet's pixels inside the image get (x, y, z, w) of their lane, or no hit
// (0, 0, 0, -1, as one ray per work-item writes) where w < 0.
inline void write_hits_packet(__constant RaycastParams* P, __global float4* hits, int gx, int gy,
                              floatN x, floatN y, floatN z, floatN w) {
  float hx[LANES], hy[LANES], hz[LANES], hw[LANES];
  vstoreN(x, 0, hx), vstoreN(y, 0, hy), vstoreN(z, 0, hz), vstoreN(w, 0, hw);
  for (int l = 0; l < LANES; ++l) {
    int px = 4 * gx + (l & 3), py = PACKET_ROWS * gy + (l >> 2);
    IMAGE_PASS_PIXEL(int, px, py);  // iso's lattice pass writes its hits (image_pass.cl)
    if (px >= P->image.x || py >= P->image.y) continue;
    hits[py * P->image.x + px] =
        hw[l] < 0.0f ? (float4)(0.0f, 0.0f, 0.0f, -1.0f) : (float4)(hx[l], hy[l], hz[l], hw[l]);
  }
}

#endif
