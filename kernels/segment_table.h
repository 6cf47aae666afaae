// The segment table of label-aware dvr (issue 34, LABELS in switches.h): per label 0 ... 255
// two float4, in a small __constant buffer beside the label map:
//   [2 l]     segment colour r, g, b and w, how much it replaces the table's colour (0: none;
//             segment-blend for a visible segment, 0 for label 0, an invisible segment or a
//             label no segment names)
//   [2 l + 1] x: the factor on the table's opacity (the segment's opacity where visible,
//             times 0 where segment-mask leaves the label out), y: the number (1 ...) of the
//             label's own transfer function (SEGMENT_TF, classification/segment_tf.cl), 0 for
//             the volume's; z, w unused
// Shared by the kernels and the engine (engine/src/segment_table.cpp fills it).
#ifndef VOXRAY_SEGMENT_TABLE_H
#define VOXRAY_SEGMENT_TABLE_H

#define VOXRAY_SEGMENT_LABELS 256
#define VOXRAY_SEGMENT_TABLE_FLOAT4S (2 * VOXRAY_SEGMENT_LABELS)

#endif
