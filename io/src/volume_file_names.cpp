// The file names of the research volume formats: compiled into every build (the CLI and the
// workstation ask even when VOXRAY_WITH_FORMATS is off, to say so instead of trying DICOM).
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "voxray/io/volume_file.h"

namespace voxray {

const std::vector<std::string>& volumeFileExtensions() {
  static const std::vector<std::string> extensions = {".nii",  ".nii.gz", ".nrrd",
                                                      ".nhdr", ".mha",    ".mhd"};
  return extensions;
}

bool isVolumeFile(const std::string& path) {
  std::string name = std::filesystem::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return std::any_of(
      volumeFileExtensions().begin(), volumeFileExtensions().end(), [&](const std::string& e) {
        return name.size() >= e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
      });
}

}  // namespace voxray
