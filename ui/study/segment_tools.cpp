#include "segment_tools.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray {

HuRange rangeFromWindow(const WindowLevel& wl) {
  return {wl.level - wl.width / 2.0, wl.level + wl.width / 2.0};
}

HuRange rangeFromTransferFunction(const RenderParams& p, HuRange values) {
  HuRange r;
  if (p.mode == Mode::Iso) {
    r = {std::min(p.isoLo, p.isoHi), std::max(p.isoLo, p.isoHi)};
  } else {
    // volumePropertyOf gives the table as the frame renders it (the preset, shifted).
    const std::vector<OpacityNode> o = volumePropertyOf(p).opacity;
    size_t first = o.size(), last = 0;
    for (size_t i = 0; i < o.size(); ++i)
      if (o[i].opacity > 0.0) {
        first = std::min(first, i);
        last = i;
      }
    if (first == o.size())
      throw inputError(
          "The transfer function is transparent everywhere: give the range by hand or take it "
          "From W/L.");
    r.lo = first == 0 ? values.lo : o[first - 1].x;
    r.hi = last + 1 == o.size() ? values.hi : o[last + 1].x;
  }
  return {std::clamp(r.lo, values.lo, values.hi), std::clamp(r.hi, values.lo, values.hi)};
}

size_t previewCount(const Volume& v, int axis, int slice, HuRange range) {
  const Mask m = thresholdSlice(v, axis, slice, range);
  size_t n = 0;
  for (uint8_t b : m) n += b != 0;
  return n;
}

SegmentRecipe thresholdRecipe(HuRange range) {
  SegmentRecipe r;
  r.threshold = range;
  return r;
}

SegmentRecipe seedRecipe(HuRange range, glm::ivec3 seed, Connectivity c) {
  SegmentRecipe r = thresholdRecipe(range);
  r.seed = seed;
  r.connectivity = c;
  return r;
}

glm::ivec3 nearestVoxel(glm::dvec3 voxel) {
  return {int(std::floor(voxel.x + 0.5)), int(std::floor(voxel.y + 0.5)),
          int(std::floor(voxel.z + 0.5))};
}

namespace {

void needSegment(const SegmentationModel& m, uint8_t label) {
  if (!m.active() || !m.segmentation().find(label))
    throw inputError("Choose a segment in the Segments panel first (or add one).");
}

}  // namespace

void brushDab(SegmentationModel& m, const SegmentToolSettings& s, int axis, glm::dvec3 voxel) {
  needSegment(m, s.label);
  const EditPolicy p{s.overwriteOthers};
  const bool paint = s.tool == SegmentTool::Paint;
  if (s.sphere) {
    if (paint)
      m.paintSphere(voxel, s.radiusMm, s.label, p);
    else
      m.eraseSphere(voxel, s.radiusMm, s.label);
  } else {
    // The disc lies in the slice itself: its index along AXIS is a whole one.
    voxel[axis] = std::floor(voxel[axis] + 0.5);
    if (paint)
      m.paintDisc(axis, voxel, s.radiusMm, s.label, p);
    else
      m.eraseDisc(axis, voxel, s.radiusMm, s.label);
  }
}

void seedClick(SegmentationModel& m, const Volume& v, const SegmentToolSettings& s,
               glm::ivec3 seed) {
  needSegment(m, s.label);
  m.applyRecipe(v, seedRecipe(s.range, seed, s.connectivity), s.label,
                EditPolicy{s.overwriteOthers});
}

void applyThreshold(SegmentationModel& m, const Volume& v, const SegmentToolSettings& s) {
  needSegment(m, s.label);
  m.applyRecipe(v, thresholdRecipe(s.range), s.label, EditPolicy{s.overwriteOthers});
}

MaskChoice maskChoiceOf(const SegmentMask& m, int label) {
  if (m.kind == SegmentMask::Kind::Off ||
      std::find(m.labels.begin(), m.labels.end(), label) == m.labels.end())
    return MaskChoice::Off;
  return m.kind == SegmentMask::Kind::Show ? MaskChoice::ShowOnly : MaskChoice::Hide;
}

SegmentMask withMaskChoice(SegmentMask m, int label, MaskChoice c) {
  std::erase(m.labels, label);
  if (c != MaskChoice::Off) {
    const auto kind = c == MaskChoice::ShowOnly ? SegmentMask::Kind::Show : SegmentMask::Kind::Hide;
    if (m.kind != kind) m.labels.clear();
    m.kind = kind;
    m.labels.insert(std::upper_bound(m.labels.begin(), m.labels.end(), label), label);
  }
  if (m.labels.empty()) m.kind = SegmentMask::Kind::Off;
  return m;
}

uint8_t segmentAt(const Segmentation& s, glm::dvec3 voxel) {
  const glm::ivec3 c = nearestVoxel(voxel);
  const glm::ivec3& d = s.grid.dims;
  const auto inside = [&](glm::ivec3 p) {
    return p.x >= 0 && p.y >= 0 && p.z >= 0 && p.x < d.x && p.y < d.y && p.z < d.z;
  };
  if (s.labels.size() != s.grid.voxelCount()) return 0;
  if (inside(c))
    if (const uint8_t l = s.labels[s.grid.index(c.x, c.y, c.z)]) return l;
  std::array<int, 256> votes{};
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        const glm::ivec3 p = c + glm::ivec3(x, y, z);
        if (inside(p)) ++votes[s.labels[s.grid.index(p.x, p.y, p.z)]];
      }
  votes[0] = 0;
  const auto best = std::max_element(votes.begin(), votes.end());
  return *best > 0 ? uint8_t(best - votes.begin()) : uint8_t(0);
}

const char* toString(MaskOperation op) {
  switch (op) {
    case MaskOperation::KeepLargest:
      return "Keep largest island";
    case MaskOperation::RemoveSmall:
      return "Remove small islands";
    case MaskOperation::FillHoles:
      return "Fill holes";
    case MaskOperation::Margin:
      return "Margin";
    case MaskOperation::Median:
      return "Median smoothing";
    case MaskOperation::Closing:
      return "Closing";
    case MaskOperation::Opening:
      return "Opening";
  }
  return "";
}

void applyOperation(SegmentationModel& m, uint8_t label, MaskOperation op, double value,
                    Connectivity c) {
  needSegment(m, label);
  if (!std::isfinite(value)) throw inputError("Give a number for the operation.");
  const Segmentation& s = m.segmentation();
  const VoxelGrid& g = s.grid;
  Mask mask = maskOf(s, label);
  switch (op) {
    case MaskOperation::KeepLargest:
      keepLargestIsland(g, mask, c);
      break;
    case MaskOperation::RemoveSmall:
      removeSmallIslands(g, mask, value, c);
      break;
    case MaskOperation::FillHoles:
      fillHoles(g, mask);
      break;
    case MaskOperation::Margin:
      applyMargin(g, mask, value);
      break;
    case MaskOperation::Median:
      medianSmooth(g, mask, value);
      break;
    case MaskOperation::Closing:
      closing(g, mask, value);
      break;
    case MaskOperation::Opening:
      opening(g, mask, value);
      break;
  }
  m.setMask(label, mask, toString(op));
}

void applyLogical(SegmentationModel& m, uint8_t target, uint8_t other, LogicalOp op) {
  needSegment(m, target);
  needSegment(m, other);
  const Mask mask = logical(m.segmentation(), target, other, op);
  // One label per voxel: adding another segment takes its voxels from it.
  const EditPolicy p{op == LogicalOp::Add};
  const char* what = op == LogicalOp::Add        ? "Add segment voxels"
                     : op == LogicalOp::Subtract ? "Subtract segment"
                                                 : "Intersect segment";
  m.setMask(target, mask, what, p);
}

}  // namespace voxray
