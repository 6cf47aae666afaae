#include "voxray/lab/accuracy_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <string>

namespace voxray {

namespace {

using Rgb = glm::ivec3;

// 3x5 glyphs, rows top to bottom: just the characters the plot writes.
const std::map<char, const char*> kGlyphs = {
    {'0', "####.##.##.####"}, {'1', ".#.##..#..#.###"}, {'2', "###..#####..###"},
    {'3', "###..####..####"}, {'4', "#.##.####..#..#"}, {'5', "####..###..####"},
    {'6', "####..####.####"}, {'7', "###..#..#..#..#"}, {'8', "####.#####.####"},
    {'9', "####.####..####"}, {'.', ".............#."}, {'-', "......###......"},
    {'A', ".#.#.#####.##.#"}, {'C', ".###..#..#...##"}, {'E', "####..##.#..###"},
    {'F', "####..##.#..#.."}, {'G', ".###..#.##.#.##"}, {'I', "###.#..#..#.###"},
    {'M', "#.#####.##.##.#"}, {'O', ".#.#.##.##.#.#."}, {'P', "##.#.###.#..#.."},
    {'R', "##.#.###.#.##.#"}, {'S', ".###...#...###."}, {'U', "#.##.##.##.####"},
    {'V', "#.##.##.##.#.#."}, {'X', "#.##.#.#.#.##.#"}, {'(', ".#.#..#..#...#."},
    {')', ".#...#..#..#.#."}, {'/', "..#..#.#.#..#.."}, {'H', "#.##.#####.##.#"},
    {'T', "###.#..#..#..#."}};

struct Canvas {
  Image img;
  Canvas(int w, int h) : img(w, h) { std::fill(img.rgba.begin(), img.rgba.end(), uint8_t(255)); }
  void dot(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    uint8_t* p = img.pixel(x, y);
    p[0] = uint8_t(c.r), p[1] = uint8_t(c.g), p[2] = uint8_t(c.b), p[3] = 255;
  }
  void line(int x0, int y0, int x1, int y1, Rgb c) {  // Bresenham
    int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0), sx = x0 < x1 ? 1 : -1,
        sy = y0 < y1 ? 1 : -1, e = dx + dy;
    for (;;) {
      dot(x0, y0, c);
      if (x0 == x1 && y0 == y1) return;
      int e2 = 2 * e;
      if (e2 >= dy) e += dy, x0 += sx;
      if (e2 <= dx) e += dx, y0 += sy;
    }
  }
  void disc(int cx, int cy, int r, Rgb c) {
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x)
        if (x * x + y * y <= r * r) dot(cx + x, cy + y, c);
  }
  void text(int x, int y, const std::string& s, Rgb c, int scale = 2) {
    for (char ch : s) {
      auto it = kGlyphs.find(ch);
      if (it != kGlyphs.end() && std::string(it->second).size() == 15)
        for (int i = 0; i < 15; ++i)
          if (it->second[i] == '#')
            for (int a = 0; a < scale; ++a)
              for (int b = 0; b < scale; ++b)
                dot(x + (i % 3) * scale + a, y + (i / 3) * scale + b, c);
      x += 4 * scale;
    }
  }
};

const Rgb kPalette[] = {{31, 119, 180}, {214, 39, 40},  {44, 160, 44}, {148, 103, 189},
                        {255, 127, 14}, {23, 190, 207}, {140, 86, 75}, {227, 119, 194}};

std::string decade(int e) {
  if (e >= 0 && e <= 4) return std::to_string(int(std::pow(10, e)));
  return "1E" + std::to_string(e);
}

struct Point {
  double ms, err;
  int scene;
};

void panel(Canvas& c, int ox, const std::vector<Point>& pts, const std::string& title) {
  const int w = 440, h = 400, left = ox + 70, top = 40, right = left + w, bottom = top + h;
  c.text(left, 12, title, {0, 0, 0});
  c.text(left + w / 2 - 50, bottom + 30, "MS PER FRAME", {0, 0, 0});
  if (pts.empty()) return;
  auto range = [&](auto get) {
    double lo = 1e300, hi = -1e300;
    for (const Point& p : pts) lo = std::min(lo, get(p)), hi = std::max(hi, get(p));
    return std::pair<int, int>(int(std::floor(std::log10(lo))), int(std::ceil(std::log10(hi))));
  };
  // Plain variables: clang 14 (the fuzz build) cannot capture structured bindings.
  const auto xs = range([](const Point& p) { return std::max(p.ms, 1e-3); });
  const auto ys = range([](const Point& p) { return std::max(p.err, 1e-9); });
  const int x0 = xs.first, x1 = std::max(xs.second, x0 + 1);
  const int y0 = ys.first, y1 = std::max(ys.second, y0 + 1);
  auto px = [&](double ms) {
    return left + int(w * (std::log10(std::max(ms, 1e-3)) - x0) / (x1 - x0));
  };
  auto py = [&](double e) {
    return bottom - int(h * (std::log10(std::max(e, 1e-9)) - y0) / (y1 - y0));
  };
  for (int e = x0; e <= x1; ++e) {
    c.line(px(std::pow(10, e)), top, px(std::pow(10, e)), bottom, {225, 225, 225});
    c.text(px(std::pow(10, e)) - 8, bottom + 8, decade(e), {0, 0, 0});
  }
  for (int e = y0; e <= y1; ++e) {
    c.line(left, py(std::pow(10, e)), right, py(std::pow(10, e)), {225, 225, 225});
    c.text(left - 60, py(std::pow(10, e)) - 5, decade(e), {0, 0, 0});
  }
  c.line(left, bottom, right, bottom, {0, 0, 0});
  c.line(left, top, left, bottom, {0, 0, 0});
  std::vector<double> ms, err;
  for (const Point& p : pts) ms.push_back(p.ms), err.push_back(p.err);
  std::vector<bool> front = paretoFront(ms, err);
  std::vector<size_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return ms[a] < ms[b]; });
  int lastX = -1, lastY = -1;
  for (size_t i : order) {
    if (!front[i]) continue;
    if (lastX >= 0) c.line(lastX, lastY, px(ms[i]), py(err[i]), {60, 60, 60});
    lastX = px(ms[i]), lastY = py(err[i]);
  }
  for (const Point& p : pts) c.disc(px(p.ms), py(p.err), 3, kPalette[p.scene % 8]);
}

}  // namespace

Image accuracyPlot(const std::vector<SweepRow>& rows) {
  Canvas c(1040, 500);
  std::map<std::string, int> scenes;
  std::vector<Point> iso, image;
  for (const SweepRow& r : rows) {
    int s = scenes.emplace(r.scene, int(scenes.size())).first->second;
    if (r.hasSurface)
      iso.push_back({r.msPerFrame, r.surface.positionVoxels.mean, s});
    else if (r.hitPoint.count > 0)
      iso.push_back({r.msPerFrame, r.hitPoint.mean, s});
    image.push_back({r.msPerFrame, r.image.rmse, s});
  }
  panel(c, 0, iso, "ISO SURFACE ERROR (VOX)");
  panel(c, 520, image, "IMAGE RMSE");
  // Legend: a colour swatch per scene, in order of appearance (names are in --json).
  int x = 820;
  for (const auto& [name, i] : scenes) c.disc(x + 24 * i, 20, 6, kPalette[i % 8]);
  return c.img;
}

}  // namespace voxray
