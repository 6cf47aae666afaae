#pragma once
// Decodes a movie back into RGBA frames with the same FFmpeg libraries that wrote it (the
// test's own reader: it converts with the BT.709 matrix the stream is tagged with).
#include <string>
#include <vector>

#include "voxray/io/image.h"

namespace voxray::test {

struct DecodedMovie {
  std::vector<Image> frames;
  std::string codec;  // "h264"
  double fps = 0.0;
};

// Throws std::runtime_error when the file cannot be decoded.
DecodedMovie decodeMovie(const std::string& path);

// Largest difference of one channel (R, G, B; alpha ignored). PSNR: the lab's compareImages.
int maxErrorRgb(const Image& a, const Image& b);

}  // namespace voxray::test
