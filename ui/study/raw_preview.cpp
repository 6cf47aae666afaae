#include "raw_preview.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "voxray/io/orientation.h"

namespace voxray {

std::optional<RawPreview> previewRawSlice(const std::string& path, const RawLayout& l) {
  auto values = readMiddleRawSlice(path, l);
  if (!values) return std::nullopt;
  auto [lo, hi] = std::minmax_element(values->begin(), values->end());
  double range = std::max(*hi - *lo, 1e-9);
  RawPreview out{Image(l.dims.x, l.dims.y), *lo, *hi};
  for (size_t i = 0; i < values->size(); ++i) {
    uint8_t g = uint8_t(255.0 * ((*values)[i] - *lo) / range);
    uint8_t* p = &out.image.rgba[i * 4];
    p[0] = p[1] = p[2] = g;
    p[3] = 255;
  }
  return out;
}

std::string valueRangeText(const RawPreview& p, const RawLayout& l) {
  double a = p.lo * l.slope + l.intercept, b = p.hi * l.slope + l.intercept;
  char text[160];
  std::snprintf(text, sizeof text, "middle slice: %g … %g", std::min(a, b), std::max(a, b));
  std::string out = text;
  // CT in HU has air at about -1000; a slice whose lowest value is far above is not in HU.
  constexpr double kAirAtMostHu = -500.0;
  if (std::min(a, b) > kAirAtMostHu)
    out += " — not HU? CT air is about −1000: set the rescale (e.g. 1, −1024)";
  return out;
}

EdgeLetters edgeLetters(const glm::dmat3& direction) {
  static const std::string letters = "LRAPSI";  // each letter beside its opposite
  auto opposite = [](char c) {
    size_t i = letters.find(c);
    return letters[i ^ 1U];
  };
  std::string code = axesCodeFromDirection(direction);
  EdgeLetters e;
  e.right = code[0];
  e.left = opposite(code[0]);
  e.bottom = code[1];
  e.top = opposite(code[1]);
  e.slices = code[2];
  return e;
}

}  // namespace voxray
