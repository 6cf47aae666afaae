#pragma once
// An 8-bit RGBA image, rows top to bottom, as produced by the renderers.
#include <cstdint>
#include <string>
#include <vector>

namespace voxray {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 0) {}
  uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
  const uint8_t* pixel(int x, int y) const {
    return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
  }
};

// Writes PNG, TIFF or EXR (chosen by the extension) through OpenImageIO, atomically:
// a temporary file beside the target, then a rename. Throws Error (Output) with the path
// and the reason.
void writeImage(const std::string& path, const Image& image);

// Reads an image (any format OpenImageIO knows) into RGBA8. Throws Error (Input).
Image readImage(const std::string& path);

}  // namespace voxray
