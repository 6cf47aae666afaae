#pragma once
// Turns the user's input (a folder, a single file or a DICOMDIR) into candidate files.
#include <string>
#include <vector>

namespace voxray::dicom {

struct InputFiles {
  std::vector<std::string> files;  // sorted, so results never depend on directory order
  bool singleFile = false;         // the user named one image file
  std::vector<std::string> notes;  // e.g. DICOMDIR entries that do not exist
};

// Throws Error (Input) when INPUT does not exist or a folder holds no files.
InputFiles collectInputFiles(const std::string& input);

}  // namespace voxray::dicom
