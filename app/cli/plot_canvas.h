#pragma once
// A tiny rasteriser for bench plots: lines, boxes and a 5x7 bitmap font, so a plot needs
// no dependency beyond the image writer voxray already has.
#include <cstdint>
#include <string>

#include "voxray/io/image.h"

namespace voxray::cli {

struct Rgb {
  uint8_t r, g, b;
};

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);
  void pixel(int x, int y, Rgb c);
  // Thick line (width w); dashed draws 8 px on, 6 px off.
  void line(double x0, double y0, double x1, double y1, Rgb c, int w = 1, bool dashed = false);
  void box(int x0, int y0, int x1, int y1, Rgb c);  // filled, inclusive
  // Text at (x, y) top-left, glyphs 5x7 scaled by `scale`; lower case prints as upper.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 2);
  static int textWidth(const std::string& s, int scale = 2) { return int(s.size()) * 6 * scale; }
  const Image& image() const { return img_; }

 private:
  Image img_;
};

}  // namespace voxray::cli
