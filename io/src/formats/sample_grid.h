#pragma once
// What a format reader hands over: one 3D grid of samples as they lie in the file, with its
// LPS geometry. volume_file.cpp checks it and turns it into a Volume.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "../raw_samples.h"

namespace voxray::formats {

struct SampleGrid {
  std::array<uint64_t, 3> dims{0, 0, 0};  // i, j, k
  glm::dvec3 spacingMm{0.0};
  glm::dvec3 originMm{0.0};   // LPS centre of voxel (0,0,0)
  glm::dmat3 direction{1.0};  // columns: LPS unit vectors of i, j, k
  detail::SampleDecoding decoding;
  // The samples (dims product of them, i fastest, then j, k), owned by `storage`: the
  // readers hand over their own buffer rather than a copy of a volume.
  std::shared_ptr<void> storage;
  const uint8_t* samples = nullptr;
  std::string sourceType;  // "i16", "f32", ...
  std::string unit = "scanner units";
  std::string modality;
  std::vector<std::string> warnings;
  int timePoint = 0, timePoints = 1;  // 4D: which 3D volume of the file this is (0-based)
};

// A format's type codes of the kinds Voxray reads, in SampleKind order (u8, i8, u16, i16,
// u32, i32, f32, f64). Returns the kind of CODE; throws Error (Input) naming TYPE_NAME when
// the code is not in the table.
using KindCodes = std::array<int, 8>;
detail::SampleKind kindOfCode(const KindCodes& codes, int code, const std::string& typeName,
                              const std::string& path);

// Name of a sample kind as Volume::sourceType spells it.
std::string kindName(detail::SampleKind kind);

// Spacing and unit directions from the three columns of an index-to-LPS matrix (each column
// is one index step in mm). Throws Error (Input) for a zero, NaN or infinite column.
void setAxes(SampleGrid& g, const glm::dmat3& stepsLps, const std::string& path);

// Refuses, before anything large is allocated, dims that are zero, overflow or exceed
// kMaxVoxels. EXTRA multiplies the count (components, time points) for the size check.
void checkDims(const std::array<uint64_t, 3>& dims, uint64_t extra, const std::string& path);

// A header's detached data file NAME, which its reader opens as CANDIDATE (NAME in the folder
// of the header PATH, or as given): returns it with its links resolved. Throws Error (Input)
// unless it is a regular file in the header's folder once links are resolved (issue 39: a
// header named /etc/passwd, or a link to a file elsewhere).
std::string dataFileInFolder(const std::string& path, const std::string& name,
                             const std::string& candidate);

}  // namespace voxray::formats
