#pragma once
// Geometry of a sorted stack of slices: spacing from positions (never SliceThickness),
// uneven gaps, missing slices and gantry tilt, and the orthogonal, uniform grid the
// volume is delivered on.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "frame_header.h"

namespace voxray::dicom {

struct Grid {
  glm::ivec3 dims{0};
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};  // LPS centre of voxel (0,0,0)
  glm::dmat3 axes{1.0};    // columns: unit vectors of i, j, k
};

struct StackGeometry {
  Grid source;  // slices as stored (k spacing = median gap)
  Grid target;  // what the volume is delivered on
  bool needsResampling = false;
  double tiltDegrees = 0.0;  // angle between the slice normal and the stacking direction
  double minGap = 0.0, maxGap = 0.0, medianGap = 0.0;
  int missingSlices = 0;
  std::vector<double> offsets;  // position of each slice along the normal, from slice 0
  std::vector<std::string> warnings;
};

// FRAMES are sorted along the normal and share one grid. Throws Error (Input) when
// the positions cannot form a volume (e.g. slices that coincide).
StackGeometry analyseStack(const std::vector<FrameHeader>& frames);

}  // namespace voxray::dicom
