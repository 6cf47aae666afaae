// log2 and exp2 for packet lanes (CPUs) in a few multiply-adds: the exponent from the
// float's bits, a polynomial for the rest. PoCL makes native_log2 its full-precision
// call; with these a CPU dvr frame (specular and opacity correction) took about 6 % less
// CPU time. GPUs keep native_ (one hardware instruction there).
#ifndef VOXRAY_MATH_LANES_CL
#define VOXRAY_MATH_LANES_CL

#include "simd/lanes.cl"

// log2 of x > 0 (normal), within 1.5e-5: log2(1 + f) for f in [0, 1) by a degree-5
// polynomial fitted for the least maximum error, exact at f = 0.
inline floatN fast_log2N(floatN x) {
  intN b = as_intN(x);
  floatN f = as_floatN((b & 0x007fffff) | 0x3f800000) - 1.0f;
  floatN p = f * (1.44196582f +
                  f * (-0.70966470f + f * (0.41760287f + f * (-0.19627960f + f * 0.04639006f))));
  return convert_floatN((b >> 23) - 127) + p;
}

// exp2, within 3e-6 relative: 2^f for f in [0, 1) by a degree-4 polynomial, times 2^n
// from the bits. Inputs below -126 give 2^-126 (as good as 0 for colours and opacity).
inline floatN fast_exp2N(floatN x) {
  x = clamp(x, -126.0f, 127.0f);
  floatN n = floor(x), f = x - n;
  floatN p = 1.0f + f * (0.69304490f + f * (0.24127987f + f * (0.05224320f + f * 0.01342623f)));
  return as_floatN((convert_intN(n) + 127) << 23) * p;
}

#endif
