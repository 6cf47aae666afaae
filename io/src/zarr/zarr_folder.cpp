// Whether a folder is an OME-Zarr: compiled into every build (the loader asks even when
// VOXRAY_WITH_ZARR is off, to say so instead of trying DICOM).
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "voxray/io/ome_zarr.h"

namespace fs = std::filesystem;

namespace voxray {

bool isOmeZarr(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return false;
  // "x.ome.zarr/" names the folder too.
  const fs::path p =
      fs::path(path).filename().empty() ? fs::path(path).parent_path() : fs::path(path);
  std::string name = p.filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return (name.size() > 5 && name.compare(name.size() - 5, 5, ".zarr") == 0) ||
         fs::exists(p / "zarr.json", ec) || fs::exists(p / ".zattrs", ec) ||
         fs::exists(p / ".zgroup", ec);
}

}  // namespace voxray
