#include "label_table.h"

#include <algorithm>
#include <array>

#include "segment_table.h"  // kernels/: the layout
#include "segment_tf.h"

namespace voxray {

std::vector<glm::vec4> segmentTable(const std::vector<Segment>& segments, const RenderParams& p) {
  constexpr int kLabels = VOXRAY_SEGMENT_LABELS;
  std::vector<glm::vec4> t(VOXRAY_SEGMENT_TABLE_FLOAT4S, glm::vec4(0.0f));
  const SegmentMask& m = p.segmentMask;
  const auto listed = [&](int label) {
    return std::binary_search(m.labels.begin(), m.labels.end(), label);
  };
  for (int l = 0; l < kLabels; ++l) {
    float keep = 1.0f;
    if (m.kind == SegmentMask::Kind::Show) keep = listed(l) ? 1.0f : 0.0f;
    if (m.kind == SegmentMask::Kind::Hide) keep = listed(l) ? 0.0f : 1.0f;
    t[2 * l + 1].x = keep;
  }
  for (const Segment& s : segments) {
    // An invisible segment is plain volume; so is one shown as a surface (the surface pass
    // draws it) or hidden in 3D.
    if (s.label == 0 || !s.visible || s.display3d != Segment::Display3d::Volume) continue;
    const int l = s.label;
    t[2 * l] = glm::vec4(glm::clamp(s.colour, 0.0f, 1.0f), float(p.segmentBlend));
    t[2 * l + 1].x *= std::clamp(s.opacity, 0.0f, 1.0f);
  }
  // Per-segment transfer functions (segment_tf.h): the table's number, and no tint (the
  // segment's own table is its colour).
  const std::array<int, 256> slots = segmentTfSlots(segments, p);
  for (int l = 1; l < kLabels; ++l)
    if (slots[size_t(l)] > 0) t[2 * l].w = 0.0f, t[2 * l + 1].y = float(slots[size_t(l)]);
  return t;
}

bool changesNothing(const std::vector<glm::vec4>& table) {
  for (size_t l = 0; l < table.size() / 2; ++l)
    if (table[2 * l].w != 0.0f || table[2 * l + 1].x != 1.0f || table[2 * l + 1].y != 0.0f)
      return false;
  return true;
}

}  // namespace voxray
