#include "bench_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "voxray/io/error.h"
#include "voxray/lab/plot_canvas.h"

namespace voxray::cli {

namespace {

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, v < 10 ? "%.1f" : "%.0f", v);
  return b;
}

}  // namespace

void writeBenchPlot(const std::string& path, const std::vector<BenchRow>& rows) {
  if (rows.empty()) throw inputError("--plot: nothing was measured");
  // Series in first-seen order; x is the pixel count (the sizes the seed used are spaced
  // that way), y is fps on a log scale so 3 and 300 fps are both readable.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const BenchRow*>> series;
  double xmax = 0, ymin = 1e30, ymax = 0;
  for (const auto& r : rows) {
    std::string key = r.input + " " + r.gradient +
                      (r.kernel == "uber"          ? " uber"
                       : r.kernel == "specialised" ? " per-ray"
                                                   : "");
    if (!series.count(key)) order.push_back(key);
    series[key].push_back(&r);
    xmax = std::max(xmax, double(r.pixels));
    for (double v : {r.fps, r.seedFps})
      if (v > 0) ymin = std::min(ymin, v), ymax = std::max(ymax, v);
  }
  double lo = std::pow(10.0, std::floor(std::log10(ymin))),
         hi = std::pow(10.0, std::ceil(std::log10(ymax)));
  const int W = 1000, H = 640, L = 90, R = 330, T = 50, B = 70;
  PlotCanvas c(W, H);
  const PlotRgb ink{30, 30, 30}, grid{225, 225, 225};
  auto X = [&](double px) { return L + (W - L - R) * px / (xmax * 1.05); };
  auto Y = [&](double fps) {
    return T + (H - T - B) *
                   (1.0 - (std::log10(fps) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)));
  };
  for (double d = lo; d <= hi * 1.001; d *= 10)
    for (double m : {1.0, 2.0, 5.0}) {
      double v = d * m;
      if (v > hi * 1.001) break;
      c.line(L, Y(v), W - R, Y(v), grid);
      c.text(L - 8 - PlotCanvas::textWidth(fmt(v)), int(Y(v)) - 7, fmt(v), ink);
    }
  std::vector<std::pair<int, std::string>> xticks;
  for (const auto& r : rows) xticks.emplace_back(r.pixels, r.size);
  std::sort(xticks.begin(), xticks.end());
  xticks.erase(std::unique(xticks.begin(), xticks.end()), xticks.end());
  for (const auto& [px, label] : xticks) {
    c.line(X(px), T, X(px), H - B, grid);
    c.text(int(X(px)) - PlotCanvas::textWidth(label, 1) / 2, H - B + 8, label, ink, 1);
  }
  c.line(L, T, L, H - B, ink, 2);
  c.line(L, H - B, W - R, H - B, ink, 2);
  c.text(L, 15, "frames per second (log) against image size", ink);
  c.text(L + 120, H - 30, "pixels: solid = voxray, dashed = seed paper (8800 GT)", ink, 1);
  for (size_t s = 0; s < order.size(); ++s) {
    PlotRgb col = seriesColour(s);
    auto pts = series[order[s]];
    std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->pixels < b->pixels; });
    for (size_t i = 0; i < pts.size(); ++i) {
      double x = X(pts[i]->pixels);
      c.box(int(x) - 3, int(Y(pts[i]->fps)) - 3, int(x) + 3, int(Y(pts[i]->fps)) + 3, col);
      if (i > 0) {
        double xp = X(pts[i - 1]->pixels);
        c.line(xp, Y(pts[i - 1]->fps), x, Y(pts[i]->fps), col, 2);
        if (pts[i]->seedFps > 0 && pts[i - 1]->seedFps > 0)
          c.line(xp, Y(pts[i - 1]->seedFps), x, Y(pts[i]->seedFps), col, 2, true);
      }
    }
    int ly = T + int(s) * 22;
    c.box(W - R + 20, ly + 3, W - R + 40, ly + 9, col);
    c.text(W - R + 48, ly, order[s], ink);
  }
  writeImage(path, c.image());
}

}  // namespace voxray::cli
