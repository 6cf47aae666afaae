#pragma once
// Writes a Volume as NRRD (Teem's writer: .nrrd, or .nhdr with detached data) or MetaImage
// (MetaIO's writer: .mha, or .mhd with .raw/.zraw), optionally with one index axis reversed
// so the file's grid differs from the volume's but means the same.
#include <string>

#include "voxray/io/volume.h"

namespace voxray::test {

// FLIP_AXIS: -1 none, else 0..2 (the data are reversed along it, origin and direction follow).
// Writes int16 when the volume stores its physical values as they are (slope 1, intercept 0),
// else float32 physical values. Throws std::runtime_error when writing fails.
void writeVolumeFile(const Volume& v, const std::string& path, int flipAxis, bool compress);

}  // namespace voxray::test
