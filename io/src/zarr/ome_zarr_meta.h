#pragma once
// The OME-NGFF multiscales metadata (0.4 in a Zarr v2 group's .zattrs, 0.5 under "ome" in a
// Zarr v3 group's zarr.json) and Voxray's own "voxray" block beside it, read into what the
// loader needs: each level's array folder, spacing and translation in mm, and the direction.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "../raw_samples.h"

namespace voxray::zarr {

struct Level {
  std::string folder;             // the level's array
  glm::dvec3 spacingMm{1.0};      // along x (i), y (j), z (k)
  glm::dvec3 translationMm{0.0};  // the centre of voxel 0 in the volume's own axes
};

struct Pyramid {
  int format = 2;  // Zarr v2 (NGFF 0.4) or v3 (NGFF 0.5)
  size_t axes = 3;
  std::vector<std::string> axisNames;
  std::vector<Level> levels;  // full resolution first
  glm::dmat3 direction{1.0};  // LPS directions of i, j, k (the voxray block; else identity)
  std::string unit = "scanner units", modality;
  std::vector<std::string> warnings;
};

// Reads FOLDER's group metadata. Throws Error (Input) naming the file and what is wrong.
Pyramid readPyramid(const std::string& folder);

// Name of a sample kind as Volume::sourceType spells it ("i16", "f32", ...).
std::string kindName(detail::SampleKind kind);

// The voxray block Voxray writes beside multiscales.
inline constexpr const char* kVoxrayBlock = "voxray";

}  // namespace voxray::zarr
