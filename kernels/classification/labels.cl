// LABELS (switches.h): label-aware dvr (issue 34). Each sample takes the label of its nearest
// voxel from the label map (uint8, x fastest, the volume's dims, beside the volume) and the
// segment table (segment_table.h): the table's colour mixed toward the segment's colour, the
// opacity times the label's factor (segment opacity, segment-mask). The factor is at most 1,
// so a sample the table leaves transparent stays so: its label is not read.
// engine/src/reference_renderer.cpp does the same in double precision.
#ifndef VOXRAY_LABELS_CL
#define VOXRAY_LABELS_CL

#include "classification/segment_tf.cl"
#include "params.cl"
#include "segment_table.h"

// The kernel's label arguments, passed on to whoever classifies dvr samples.
#if LABELS
// SEGMENT_TF: the segments' own tables too (segment_tf.cl).
#define LABEL_PARAMS , __global const uchar *restrict labels, __constant float4 *segs SEGTF_PARAMS
#define LABEL_PASS , labels, segs SEGTF_PASS

// The label of the voxel nearest to p (voxel coordinates, centres at integers), clamped to
// the edge as sample_slab's nearest read.
inline int label_at(__global const uchar* restrict labels, __constant RaycastParams* P, float3 p) {
  int3 i = clamp(convert_int3(floor(p + 0.5f)), (int3)(0), P->dims.xyz - 1);
  return labels[((size_t)i.z * P->dims.y + i.y) * P->dims.x + i.x];
}

// Table colour and opacity c classified by label l.
inline float4 label_classify(__constant float4* segs, int l, float4 c) {
  float4 s = segs[2 * l];
  return (float4)(mix(c.xyz, s.xyz, s.w), c.w * segs[2 * l + 1].x);
}
#else
#define LABEL_PARAMS
#define LABEL_PASS
#endif

#endif
