// Table lookups for ray packets, the lane-by-lane twin of lut.cl.
#ifndef VOXRAY_LUT_LANES_CL
#define VOXRAY_LUT_LANES_CL

#include "classification/lut.cl"
#include "reconstruction/sampling_lanes.cl"
#include "simd/lanes.cl"

// Where each lane's value falls in the table (lut_lookup, march.cl): entries *k and *k1,
// mixed by *f.
inline void lut_spotN(__constant RaycastParams* P, floatN v, intN* k, intN* k1, floatN* f) {
  int last = P->dims.w - 1;
  floatN x = clamp((v - P->values.z) * P->values.w, 0.0f, (float)last);
  floatN x0 = floor(x);
  *f = x - x0;
  *k = convert_intN(x0);
  *k1 = min(*k + 1, last);
}

// Only the opacity: two gathers (dvr with shading looks the colour up when it shades).
inline floatN lut_alphaN(__global const float4* lut, __constant RaycastParams* P, floatN v) {
  intN k, k1;
  floatN f;
  lut_spotN(P, v, &k, &k1, &f);
  __global const float* alpha = (__global const float*)lut + 3;
  return mix(gather_floatN(alpha, 4 * k), gather_floatN(alpha, 4 * k1), f);
}

// lut_lookup for each lane's value, as four channels. Each lane mixes its two entries as a
// float4; the results are transposed in registers.
inline void lutN(__global const float4* lut, __constant RaycastParams* P, floatN v,
                 floatN rgba[4]) {
  intN k, k1;
  floatN f;
  lut_spotN(P, v, &k, &k1, &f);
  float4 e[LANES];
#define LUT_LANE(l, n) e[n] = mix(lut[k.s##l], lut[k1.s##l], f.s##l);
#define LUT_X(l, n) e[n].x
#define LUT_Y(l, n) e[n].y
#define LUT_Z(l, n) e[n].z
#define LUT_W(l, n) e[n].w
  LANE_EACH(LUT_LANE)
  rgba[0] = (floatN)(LANE_LIST(LUT_X));
  rgba[1] = (floatN)(LANE_LIST(LUT_Y));
  rgba[2] = (floatN)(LANE_LIST(LUT_Z));
  rgba[3] = (floatN)(LANE_LIST(LUT_W));
#undef LUT_LANE
#undef LUT_X
#undef LUT_Y
#undef LUT_Z
#undef LUT_W
}

#endif
