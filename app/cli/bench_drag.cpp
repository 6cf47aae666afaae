#include "bench_drag.h"

#include <algorithm>
#include <cstdio>

#include "render_state_model.h"

namespace voxray::cli {

namespace {

// The Q-quantile of MS (nearest rank).
double quantile(std::vector<double> ms, double q) {
  if (ms.empty()) return 0.0;
  std::sort(ms.begin(), ms.end());
  return ms[std::min(ms.size() - 1, size_t(q * double(ms.size())))];
}

}  // namespace

DragReplay replayDrag(Raycaster& rc, const RenderParams& base, const glm::ivec2& view,
                      double minSpacingMm, Orbit orbit, int frames, double targetFps) {
  ui::AdaptiveQuality adaptive(targetFps, ui::dragPresetSetting());
  ui::Quality quality;
  quality.dragFps = targetFps;
  RenderParams b = base;
  Image image;
  DragReplay d;
  d.frames = frames;
  std::vector<double> start;
  for (int i = 0; i < frames; ++i) {
    orbitCamera(b.camera, orbit, i, 180);
    const RenderParams p = ui::planFrame(b, quality, view, true, minSpacingMm, &adaptive.setting());
    FrameStats stats;
    rc.render(p, image, &stats);
    if (d.path.empty())
      start.push_back(stats.totalMs);
    else
      d.adaptedMs.push_back(stats.totalMs), d.adaptedWidths.push_back(p.width);
    // As RenderScheduler::onFrame reads the setting back from the frame.
    const int before = adaptive.changes();
    adaptive.record(stats.totalMs, ui::dragSettingOf(p, view.x, minSpacingMm));
    if (adaptive.changes() != before)
      d.path.push_back({i, adaptive.setting().scale, adaptive.setting().stepVoxels});
  }
  d.startMedianMs = quantile(start, 0.5);
  if (d.path.empty()) d.adaptedMs = start;
  return d;
}

void printDragReplay(const DragReplay& d, double targetFps) {
  const double budget = 1000.0 / targetFps;
  const double within = double(std::count_if(d.adaptedMs.begin(), d.adaptedMs.end(),
                                             [&](double ms) { return ms <= budget; })) /
                        double(std::max<size_t>(d.adaptedMs.size(), 1));
  const auto [lo, hi] = std::minmax_element(d.adaptedWidths.begin(), d.adaptedWidths.end());
  const double median = quantile(d.adaptedMs, 0.5);
  std::printf(
      "drag replay: %d frames toward %.0f fps; the drag preset's own frames: median %.1f ms; "
      "%zu setting changes; the %zu frames after the first (widths %d-%d): median %.1f ms "
      "(%.1f fps), 90th percentile %.1f ms, %.0f %% within %.1f ms\n",
      d.frames, targetFps, d.startMedianMs, d.path.size(), d.adaptedMs.size(),
      lo == d.adaptedWidths.end() ? 0 : *lo, hi == d.adaptedWidths.end() ? 0 : *hi, median,
      median > 0 ? 1000.0 / median : 0.0, quantile(d.adaptedMs, 0.9), 100.0 * within, budget);
  for (const DragChange& c : d.path)
    std::printf("  after frame %d: scale %.3f, step %.2f voxels\n", c.frame, c.scale, c.stepVoxels);
  std::fflush(stdout);
}

}  // namespace voxray::cli
