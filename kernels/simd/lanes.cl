// The width of a ray packet (march_lanes.cl): LANES rays per work-item, 4 across and
// PACKET_ROWS down, in floatN vectors. 8 fills AVX2; 16 fills AVX-512, where it ran dvr
// 1.22x faster (the host picks it from the device's native float width).
#ifndef VOXRAY_LANES_CL
#define VOXRAY_LANES_CL

#ifndef LANES
#define LANES 8
#endif
#define PACKET_ROWS (LANES / 4)

// LANE_LIST(F): F(l, n) for every lane, comma-separated; LANE_EACH(F): the same without
// commas (statements). l is the lane's vector component suffix (v.s##l), n its index.
#if LANES == 8
typedef float8 floatN;
typedef int8 intN;
typedef uint8 uintN;
typedef short8 shortN;
typedef uchar8 ucharN;
#define convert_floatN convert_float8
#define convert_intN convert_int8
#define as_uintN as_uint8
#define as_intN as_int8
#define as_floatN as_float8
#define vstoreN vstore8
#define vloadN vload8
#define LANE_LIST(F) F(0, 0), F(1, 1), F(2, 2), F(3, 3), F(4, 4), F(5, 5), F(6, 6), F(7, 7)
#define LANE_EACH(F) F(0, 0) F(1, 1) F(2, 2) F(3, 3) F(4, 4) F(5, 5) F(6, 6) F(7, 7)
#elif LANES == 16
typedef float16 floatN;
typedef int16 intN;
typedef uint16 uintN;
typedef short16 shortN;
typedef uchar16 ucharN;
#define convert_floatN convert_float16
#define convert_intN convert_int16
#define as_uintN as_uint16
#define as_intN as_int16
#define as_floatN as_float16
#define vstoreN vstore16
#define vloadN vload16
// clang-format does not settle on one layout of these lists.
// clang-format off
#define LANE_LIST(F)                                                                       \
  F(0, 0), F(1, 1), F(2, 2), F(3, 3), F(4, 4), F(5, 5), F(6, 6), F(7, 7), F(8, 8), F(9, 9), \
  F(a, 10), F(b, 11), F(c, 12), F(d, 13), F(e, 14), F(f, 15)
#define LANE_EACH(F)                                                                   \
  F(0, 0) F(1, 1) F(2, 2) F(3, 3) F(4, 4) F(5, 5) F(6, 6) F(7, 7) F(8, 8) F(9, 9) \
  F(a, 10) F(b, 11) F(c, 12) F(d, 13) F(e, 14) F(f, 15)
// clang-format on
#else
#error "LANES must be 8 or 16"
#endif

// How many lanes of a mask are set.
inline int count_lanes(intN m) {
  intN b = m & 1;
#if LANES == 16
  int8 h8 = b.lo + b.hi;
#else
  int8 h8 = b;
#endif
  int4 h = h8.lo + h8.hi;
  return h.x + h.y + h.z + h.w;
}

#endif
