// The per-pixel jitter of JITTER 1, one formula for the scalar kernels (uint), the packets
// (uintN lanes) and the C++ reference renderer (uint32_t), so that all three agree bit for
// bit: 24 bits of a hash of the pixel, as a fraction VOXRAY_JITTER_HASH / VOXRAY_JITTER_RANGE
// in [0, 1). px and py must already be 32-bit unsigned, whose arithmetic wraps alike in
// OpenCL C and C++.
#ifndef VOXRAY_JITTER_HASH_H
#define VOXRAY_JITTER_HASH_H

#define VOXRAY_JITTER_MIX0(px, py) ((px)*73856093u ^ (py)*19349663u)
#define VOXRAY_JITTER_MIX1(h) (((h) ^ ((h) >> 13)) * 0x5bd1e995u)
#define VOXRAY_JITTER_MIX2(h) ((h) ^ ((h) >> 15))
#define VOXRAY_JITTER_HASH(px, py) \
  (VOXRAY_JITTER_MIX2(VOXRAY_JITTER_MIX1(VOXRAY_JITTER_MIX0(px, py))) & 0xffffffu)
#define VOXRAY_JITTER_RANGE 16777216.0f

#endif
