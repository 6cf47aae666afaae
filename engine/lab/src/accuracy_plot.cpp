#include "voxray/lab/accuracy_plot.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

#include "voxray/lab/plot_canvas.h"

namespace voxray {

namespace {

const PlotRgb kInk{0, 0, 0}, kGrid{225, 225, 225}, kFrontier{60, 60, 60};

std::string decade(int e) {
  if (e >= 0 && e <= 4) return std::to_string(int(std::pow(10, e)));
  return "1E" + std::to_string(e);
}

struct Point {
  double ms, err;
  int scene;
};

void panel(PlotCanvas& c, int ox, const std::vector<Point>& pts, const std::string& title) {
  const int w = 440, h = 400, left = ox + 70, top = 40, right = left + w, bottom = top + h;
  c.text(left, 12, title, kInk);
  const std::string xTitle = "MS PER FRAME";
  c.text(left + (w - PlotCanvas::textWidth(xTitle)) / 2, bottom + 30, xTitle, kInk);
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
    c.line(px(std::pow(10, e)), top, px(std::pow(10, e)), bottom, kGrid);
    // Centred under its line, but never cut off by the right edge (it would read 100 for 1000).
    const int tw = PlotCanvas::textWidth(decade(e));
    c.text(std::min(px(std::pow(10, e)) - tw / 2, c.image().width - tw), bottom + 8, decade(e),
           kInk);
  }
  for (int e = y0; e <= y1; ++e) {
    c.line(left, py(std::pow(10, e)), right, py(std::pow(10, e)), kGrid);
    c.text(left - 8 - PlotCanvas::textWidth(decade(e)), py(std::pow(10, e)) - 7, decade(e), kInk);
  }
  c.line(left, bottom, right, bottom, kInk);
  c.line(left, top, left, bottom, kInk);
  std::vector<double> ms, err;
  for (const Point& p : pts) ms.push_back(p.ms), err.push_back(p.err);
  std::vector<bool> front = paretoFront(ms, err);
  std::vector<size_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return ms[a] < ms[b]; });
  int lastX = -1, lastY = -1;
  for (size_t i : order) {
    if (!front[i]) continue;
    if (lastX >= 0) c.line(lastX, lastY, px(ms[i]), py(err[i]), kFrontier);
    lastX = px(ms[i]), lastY = py(err[i]);
  }
  for (const Point& p : pts) c.disc(px(p.ms), py(p.err), 3, seriesColour(size_t(p.scene)));
}

}  // namespace

Image accuracyPlot(const std::vector<SweepRow>& rows) {
  PlotCanvas c(1040, 500);
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
  for (const auto& [name, i] : scenes) c.disc(x + 24 * i, 20, 6, seriesColour(size_t(i)));
  return c.image();
}

}  // namespace voxray
