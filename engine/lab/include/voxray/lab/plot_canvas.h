#pragma once
// The one rasteriser behind voxray's plots (`accuracy --plot`, `bench --plot`): lines,
// boxes, discs and a 5x7 bitmap font into an Image, so a plot needs nothing beyond the
// image writer voxray already has. Debian's plotting libraries (PLplot, MathGL, GNU
// plotutils) would bring Fortran, Qt5, HDF5 or X11 for two charts.
#include <cstddef>
#include <cstdint>
#include <string>

#include "voxray/io/image.h"

namespace voxray {

struct PlotRgb {
  uint8_t r, g, b;
};

// Series colours in order (Tableau 10); the index wraps.
PlotRgb seriesColour(size_t i);

class PlotCanvas {
 public:
  PlotCanvas(int width, int height, PlotRgb background = {255, 255, 255});
  void pixel(int x, int y, PlotRgb c);  // outside the canvas: nothing
  // Line of width w; dashed draws 8 px on, 6 px off.
  void line(double x0, double y0, double x1, double y1, PlotRgb c, int w = 1, bool dashed = false);
  void box(int x0, int y0, int x1, int y1, PlotRgb c);  // filled, inclusive
  void disc(int cx, int cy, int radius, PlotRgb c);     // filled
  // Text at (x, y) top-left, glyphs 5x7 scaled by `scale`; lower case prints as upper,
  // characters without a glyph as a space.
  void text(int x, int y, const std::string& s, PlotRgb c, int scale = 2);
  static int textWidth(const std::string& s, int scale = 2) { return int(s.size()) * 6 * scale; }
  static int textHeight(int scale = 2) { return 7 * scale; }
  const Image& image() const { return img_; }

 private:
  Image img_;
};

}  // namespace voxray
