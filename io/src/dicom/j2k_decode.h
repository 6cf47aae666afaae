#pragma once
// JPEG 2000 decoding with OpenJPEG (DCMTK ships no free JPEG 2000 codec).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace voxray::dicom {

struct J2kImage {
  int width = 0, height = 0, components = 0;
  int precision = 0;
  bool isSigned = false;
  std::vector<int32_t> samples;  // first component only, row by row
};

// Decodes a J2K codestream or JP2 file held in memory. Partial (truncated) streams fail.
// Throws Error (Input) with a reason; the caller adds the file name.
J2kImage decodeJpeg2000(const uint8_t* data, size_t size);

}  // namespace voxray::dicom
