#pragma once
// The sequence of operations that makes a segment from a threshold: the one implementation
// that voxray-cli segment and the workstation's editor both run, so the CLI's label map is
// the workstation's voxel for voxel.
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "voxray/io/segment_edit.h"
#include "voxray/io/segment_ops.h"

namespace voxray {

struct SegmentRecipe {
  HuRange threshold;
  std::optional<glm::ivec3> seed;  // voxel index: the region connected to it, else all voxels
  Connectivity connectivity = Connectivity::Faces6;
  bool keepLargest = false;
  bool fillHoles = false;
  double marginMm = 0.0;  // > 0 grows, < 0 shrinks
  double smoothMm = 0.0;  // median kernel diameter; 0 = none
  std::string name = "Segment";
  glm::vec3 colour{0.9f, 0.85f, 0.7f};
};

// In this order: threshold (or the seeded region), keep largest island, fill holes, margin,
// smoothing. Throws an input Error for a bad range or seed.
Mask runRecipe(const Volume& v, const SegmentRecipe& r);

// The seed given in LPS millimetres, as its nearest voxel; throws an input Error when outside.
glm::ivec3 seedFromMm(const Volume& v, glm::dvec3 lpsMm);

// A new segmentation on the volume's grid with the recipe's mask as segment 1.
Segmentation segmentationFromRecipe(const Volume& v, const SegmentRecipe& r);

}  // namespace voxray
