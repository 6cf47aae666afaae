#pragma once
// The OME-NGFF multiscales metadata (0.4 in a Zarr v2 group's .zattrs, 0.5 under "ome" in a
// Zarr v3 group's zarr.json) and Voxray's own "voxray" block beside it, read into what the
// loader needs: each level's array folder, spacing and translation in mm, and the direction.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <nlohmann/json.hpp>

#include "../raw_samples.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/volume.h"

namespace voxray::zarr {

struct Level {
  std::string path;               // the level's array: its key prefix in the store
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
  // Level 0's smallest and largest value, when Voxray wrote them (voxray.level0-range).
  std::optional<ValueRange> level0Range;
  std::vector<std::string> warnings;
};

// Reads the group metadata at the root of STORE (zarr.json, else .zattrs/.zgroup). Throws
// Error (Input) naming the file and what is wrong.
Pyramid readPyramid(ZarrStore& store);
// The same from the group's parsed DOCUMENT (v3: zarr.json; v2: .zattrs) of Zarr FORMAT,
// named FILE in messages (the fuzz target's entry: no store).
Pyramid parsePyramid(int format, const nlohmann::json& document, const std::string& file);

struct ArrayMeta;

// Throws Error (Input) naming WHERE when INDEX is not one of the pyramid's levels.
void checkLevelIndex(const Pyramid& pyramid, int index, const std::string& where);
// Level INDEX, whose array metadata is M, as a Volume without voxels: dims, spacing, origin,
// direction, unit, modality, source type and the pyramid's warnings. Throws Error (Input) when
// the array's rank is not the axes' or it has more voxels than a Volume holds.
Volume describeLevel(const Pyramid& pyramid, int index, const ArrayMeta& m,
                     const std::string& where);

// Name of a sample kind as Volume::sourceType spells it ("i16", "f32", ...).
std::string kindName(detail::SampleKind kind);

// The voxray block Voxray writes beside multiscales.
inline constexpr const char* kVoxrayBlock = "voxray";

}  // namespace voxray::zarr
