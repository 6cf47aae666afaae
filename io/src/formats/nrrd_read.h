#pragma once
// NRRD (.nrrd, .nhdr with detached raw or gzip data) through Teem's nrrd library. Not ITK's
// NrrdImageIO: ITK 5.2 turns "left-anterior-superior" into LPS by negating x instead of y
// (a silent left/right and front/back error), which the NRRD tests here would catch.
#include <string>

#include "sample_grid.h"

namespace voxray::formats {

// Geometry: `space directions` and `space origin` in any anatomical space (RAS, LAS, LPS and
// their time variants) become LPS; scanner or 3D-handed spaces and files with spacings only
// are taken as LPS with a warning. Throws Error (Input).
SampleGrid readNrrd(const std::string& path);

}  // namespace voxray::formats
