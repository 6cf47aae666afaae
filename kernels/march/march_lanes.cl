// What iso, dvr and mip packets share (iso_packet.cl, dvr_packet.cl, mip_packet.cl, one
// algorithm each): on CPUs one work-item marches a packet of 4 x PACKET_ROWS neighbouring
// rays in floatN lanes (simd/lanes.cl). PoCL runs a per-ray loop as scalar code, one ray at
// a time; here the arithmetic of LANES rays shares each vector instruction and only the
// volume loads stay scalar. The algorithms are march.cl's lane by lane: the same samples,
// the same empty-space leaps (skip.cl's ess_leap), the same bisection, so the image is the
// same. Lanes whose ray is done are masked; the packet runs until its last ray is. Volumes
// here are buffers (STORAGE_IMAGE 0) of fewer than 2^31 voxels (int indices). Their tuning
// (ISO_BATCH, DVR_BATCH, MIP_REFILL, ...) is a -D literal per LANES: switches.h.
#ifndef VOXRAY_MARCH_LANES_CL
#define VOXRAY_MARCH_LANES_CL

#include "march/march.cl"
#include "shading/shading_lanes.cl"
#include "simd/lanes.cl"
#if HIT_OUTPUT
#include "march/hit_output_lanes.cl"
// The kernel's hits, passed on to iso and dvr packets (PACKET_ARGS).
#define PACKET_HITS , __global float4* hits
#define PACKET_HITS_ARG , hits
#else
#define PACKET_HITS
#define PACKET_HITS_ARG
#endif

#ifndef ISO_BATCH
#error "packets need the tuning -D options of switches.h (engine/src/kernel_switches.cpp)"
#endif

// What iso and dvr packets take (LABELS: the label map and segment table too, which only dvr
// reads): the kernel's arguments and the packet's place (gx, gy).
#define PACKET_ARGS                                                                            \
  __global const short *restrict vol, __constant RaycastParams *P, __global const float4 *lut, \
      __global uchar4 *out, CELL_ARGS, __global uint *count, int gx,                           \
      int gy PACKET_HITS LABEL_PARAMS OVERLAY_PARAMS SURFACE_PARAMS

// Writes the packet's pixels that lie inside the image, and adds its samples to a counter.
inline void write_packet(__constant RaycastParams* P, __global uchar4* out, __global uint* count,
                         int gx, int gy, VecN color, intN samples) {
  float cr[LANES], cg[LANES], cb[LANES];
  int counts[LANES];
  vstoreN(color.x, 0, cr), vstoreN(color.y, 0, cg), vstoreN(color.z, 0, cb);
  vstoreN(samples, 0, counts);
  uint total = 0;
  for (int l = 0; l < LANES; ++l) {
    int px = 4 * gx + (l & 3), py = PACKET_ROWS * gy + (l >> 2);
    IMAGE_PASS_PIXEL(int, px, py);  // as pixel_raysN's
    if (px >= P->image.x || py >= P->image.y) continue;
    out[py * P->image.x + px] = to_rgba8((float3)(cr[l], cg[l], cb[l]));
    total += counts[l];
  }
  if (COUNT_SAMPLES) atomic_add(&count[(gx ^ gy) & 63], total);
}

#endif
