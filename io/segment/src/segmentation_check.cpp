#include "voxray/io/segmentation_check.h"

#include <array>
#include <sstream>

#include "voxray/io/error.h"

namespace voxray {
namespace {

std::string describe(const VoxelGrid& g) {
  std::ostringstream s;
  s << g.dims.x << "x" << g.dims.y << "x" << g.dims.z << " voxels of " << g.spacingMm.x << " x "
    << g.spacingMm.y << " x " << g.spacingMm.z << " mm at (" << g.originMm.x << ", " << g.originMm.y
    << ", " << g.originMm.z << ") mm";
  return s.str();
}

}  // namespace

void checkSegmentation(const Segmentation& s) {
  if (s.labels.size() != s.grid.voxelCount())
    throw inputError("The segmentation has " + std::to_string(s.labels.size()) +
                     " labels for a grid of " + std::to_string(s.grid.voxelCount()) +
                     " voxels: it does not belong to this volume. Make it again on this volume.");
  std::array<bool, 256> used{};
  for (const auto& segment : s.segments) {
    if (segment.label == 0)
      throw inputError("Segment \"" + segment.name +
                       "\" has label 0, which means no segment: give it a label from 1 to 255.");
    if (used[segment.label])
      throw inputError("Two segments use label " + std::to_string(segment.label) +
                       ": give each segment a label of its own.");
    used[segment.label] = true;
  }
}

void checkSameGrid(const Segmentation& s, const Volume& v) {
  if (!sameGrid(s.grid, gridOf(v)))
    throw inputError("The label map's geometry (" + describe(s.grid) +
                     ") does not match the volume's (" + describe(gridOf(v)) +
                     "): it was made on another series or resampled. Open it on its own series.");
}

}  // namespace voxray
