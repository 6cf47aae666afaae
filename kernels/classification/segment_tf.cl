// SEGMENT_TF (switches.h): per-segment transfer functions (issue 35) in label-aware dvr. A
// segment may carry its own 1D table, the volume table's layout and HU mapping (lut.cl: P->dims.w
// entries from stored value P->values.z), all of them in one buffer, table s (1 ...) at entries
// (s - 1) P->dims.w ...; the segment table's y (segment_table.h) holds each label's s, 0 where
// the label keeps the volume's table. A sample whose nearest voxel (label_at) has its own table
// is classified by it instead of the volume's; the segment's opacity factor and mask still
// apply, its tint does not (the table is its colour: the engine leaves its weight at 0).
// Its label must be read before the volume table's opacity can say "transparent", so this
// variant reads every sample's label; frames without such tables compile without it (#if).
// engine/src/reference_renderer.cpp does the same in double precision.
#ifndef VOXRAY_SEGMENT_TF_CL
#define VOXRAY_SEGMENT_TF_CL

#include "classification/lut.cl"

#if SEGMENT_TF
// Appended to LABEL_PARAMS / LABEL_PASS (labels.cl).
#define SEGTF_PARAMS , __global const float4* restrict segtf
#define SEGTF_PASS , segtf

// Label l's table (0: none, the volume's).
inline int segment_tf_slot(__constant float4* segs, int l) { return (int)segs[2 * l + 1].y; }

// C (the volume table's colour and opacity at stored value v) or, where label l has its own
// table, that table's.
inline float4 segment_tf(__global const float4* segtf, __constant float4* segs,
                         __constant RaycastParams* P, int l, float v, float4 c) {
  int s = segment_tf_slot(segs, l);
  return s > 0 ? lut_lookup(segtf + (size_t)(s - 1) * (size_t)P->dims.w, P, v) : c;
}
#else
#define SEGTF_PARAMS
#define SEGTF_PASS
#endif

#endif
