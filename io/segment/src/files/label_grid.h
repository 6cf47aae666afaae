#pragma once
// A label map as a NIfTI or NRRD file holds it, before it is placed on a volume.
#include <string>
#include <vector>

#include "voxray/io/segmentation.h"

namespace voxray::segfiles {

struct LabelFile {
  VoxelGrid grid;
  std::vector<uint8_t> labels;    // grid.voxelCount(), x fastest
  std::vector<Segment> segments;  // those the file names; unnamed labels are added later
};

// The file's labels on ONTO's grid. The file's grid must be ONTO's, or a box of it (same
// spacing and axes, first voxel on one of ONTO's voxels: Slicer crops .seg.nrrd to the
// segments' extent); otherwise an Input error names the difference. Labels no segment names
// get a segment "Label N" of their own, in a colour of a fixed palette.
Segmentation placeOnVolume(LabelFile file, const Volume& onto, const std::string& path);

// Label values must be whole numbers 0..255: the reason (with PATH) when VALUE is not.
std::string labelValueProblem(double value, const std::string& path);

}  // namespace voxray::segfiles
