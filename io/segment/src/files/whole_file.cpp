#include "whole_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "voxray/io/error.h"
#include "voxray/io/temporary_file.h"

namespace voxray::segfiles {
namespace {

namespace fs = std::filesystem;

std::string triple(const glm::dvec3& v) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

}  // namespace

std::string wholeExtension(const std::string& path) {
  std::string name = fs::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  for (const char* known : {".seg.nrrd", ".nii.gz", ".nii", ".nrrd", ".nhdr", ".dcm"}) {
    const std::string k = known;
    if (name.size() > k.size() && name.compare(name.size() - k.size(), k.size(), k) == 0) return k;
  }
  return fs::path(name).extension().string();
}

void writeWhole(const std::string& path, bool force,
                const std::function<void(const std::string& temporary)>& write) {
  const fs::path target(path);
  std::error_code ec;
  if (fs::exists(target, ec) && !force)
    throw outputError(path + " exists already: choose another name, or allow overwriting it");
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec))
    throw outputError(path + ": the folder " + folder.string() + " does not exist");
  const fs::path temporary = temporaryBeside(target, wholeExtension(path));
  try {
    write(temporary.string());
    if (!fs::exists(temporary, ec) || fs::file_size(temporary, ec) == 0)
      throw outputError(path + ": nothing could be written (is the disk full or read-only?)");
    fs::rename(temporary, target, ec);
    if (ec) throw outputError(path + ": cannot be written (" + ec.message() + ")");
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
}

void checkOnGrid(const VoxelGrid& file, const VoxelGrid& volume, const std::string& path) {
  if (sameGrid(file, volume)) return;
  std::string what;
  if (file.dims != volume.dims) {
    what = "its size is " + std::to_string(file.dims.x) + "x" + std::to_string(file.dims.y) + "x" +
           std::to_string(file.dims.z) + " voxels, the volume's " + std::to_string(volume.dims.x) +
           "x" + std::to_string(volume.dims.y) + "x" + std::to_string(volume.dims.z);
  } else if (glm::any(
                 glm::greaterThan(glm::abs(file.spacingMm - volume.spacingMm), glm::dvec3(1e-4)))) {
    what = "its spacing is " + triple(file.spacingMm) + " mm, the volume's " +
           triple(volume.spacingMm) + " mm";
  } else if (glm::any(
                 glm::greaterThan(glm::abs(file.originMm - volume.originMm), glm::dvec3(1e-4)))) {
    what = "its first voxel lies at " + triple(file.originMm) + " mm (LPS), the volume's at " +
           triple(volume.originMm) + " mm";
  } else {
    what = "its axes point elsewhere: i " + triple(file.direction[0]) + ", j " +
           triple(file.direction[1]) + ", k " + triple(file.direction[2]) + "; the volume's i " +
           triple(volume.direction[0]) + ", j " + triple(volume.direction[1]) + ", k " +
           triple(volume.direction[2]);
  }
  throw inputError(path + ": the label map does not lie on this volume's voxels (" + what +
                   "). Open it on the volume it was made on, or resample it to this one first.");
}

}  // namespace voxray::segfiles
