// The path tracer's counter-based random numbers, one formula for the kernel
// (kernels/lighting/path_trace.cl, uint) and the C++ reference (engine/src/path_reference.cpp,
// uint32_t): draw i of the path (seed, pixel, sample) is a hash of those four counters, so
// a pixel's estimate depends on nothing but them (no state carried between work-items,
// passes or devices). The hash is Wellons' lowbias32 (two multiply-xorshift rounds).
// Included by the kernel and the engine.
#ifndef VOXRAY_PATH_RNG_H
#define VOXRAY_PATH_RNG_H

#ifdef __OPENCL_VERSION__
typedef uint voxray_u32;
#else
#include <cstdint>
typedef uint32_t voxray_u32;
#endif

inline voxray_u32 voxray_hash32(voxray_u32 h) {
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

// The key of one path: pixel index (row-major) and sample index under a seed.
inline voxray_u32 voxray_path_key(voxray_u32 seed, voxray_u32 pixel, voxray_u32 sample) {
  return voxray_hash32(seed ^ voxray_hash32(pixel ^ voxray_hash32(sample * 0x9e3779b9u + 1u)));
}

// Draw `i` of the path `key` as 24 bits; uniform in [0, 1) is that times 2^-24.
inline voxray_u32 voxray_path_bits(voxray_u32 key, voxray_u32 i) {
  return voxray_hash32(key ^ voxray_hash32(i + 0x632be5abu)) >> 8;
}
#define VOXRAY_PATH_UNIT 5.9604644775390625e-8  // 2^-24

#endif
