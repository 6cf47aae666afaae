// label_at and label_classify (labels.cl) for each lane of a packet.
#ifndef VOXRAY_LABELS_LANES_CL
#define VOXRAY_LABELS_LANES_CL

#include "classification/labels.cl"
#include "simd/lanes.cl"

#if LABELS
inline intN label_atN(__global const uchar* restrict labels, __constant RaycastParams* P, floatN x,
                      floatN y, floatN z) {
  intN ix = clamp(convert_intN(floor(x + 0.5f)), (intN)(0), (intN)(P->dims.x - 1));
  intN iy = clamp(convert_intN(floor(y + 0.5f)), (intN)(0), (intN)(P->dims.y - 1));
  intN iz = clamp(convert_intN(floor(z + 0.5f)), (intN)(0), (intN)(P->dims.z - 1));
  intN k = (iz * P->dims.y + iy) * P->dims.x + ix;  // packets: volumes under 2^31 voxels
#define LABEL_LANE(l, n) labels[k.s##l]
  return convert_intN((ucharN)(LANE_LIST(LABEL_LANE)));
#undef LABEL_LANE
}

// Each lane's opacity factor.
inline floatN label_opacityN(__constant float4* segs, intN lab) {
#define FACTOR_LANE(l, n) segs[2 * lab.s##l + 1].x
  return (floatN)(LANE_LIST(FACTOR_LANE));
#undef FACTOR_LANE
}

// Each lane's colour c[0..2] mixed toward its segment's colour.
inline void label_colourN(__constant float4* segs, intN lab, floatN c[3]) {
  float4 e[LANES];
#define SEG_LANE(l, n) e[n] = segs[2 * lab.s##l];
#define SEG_X(l, n) e[n].x
#define SEG_Y(l, n) e[n].y
#define SEG_Z(l, n) e[n].z
#define SEG_W(l, n) e[n].w
  LANE_EACH(SEG_LANE)
  floatN w = (floatN)(LANE_LIST(SEG_W));
  c[0] = mix(c[0], (floatN)(LANE_LIST(SEG_X)), w);
  c[1] = mix(c[1], (floatN)(LANE_LIST(SEG_Y)), w);
  c[2] = mix(c[2], (floatN)(LANE_LIST(SEG_Z)), w);
#undef SEG_LANE
#undef SEG_X
#undef SEG_Y
#undef SEG_Z
#undef SEG_W
}
#endif  // LABELS

#endif
