#pragma once
// The segment table of label-aware dvr (issue 34; layout in kernels/segment_table.h), made
// from a segmentation's segments and a frame's segment-mask and segment-blend. The raycaster
// uploads it beside the label map; the reference renderer reads the same numbers.
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// 2 x 256 entries: per label its colour and blend weight, then its opacity factor and the
// number of its own transfer function (segment_tf.h; 0: none).
std::vector<glm::vec4> segmentTable(const std::vector<Segment>& segments, const RenderParams& p);
// Whether TABLE leaves every sample as it is (no weight, every factor 1, no own table): such a
// frame renders without labels, with exactly the pixels of a raycaster that has none.
bool changesNothing(const std::vector<glm::vec4>& table);

}  // namespace voxray
