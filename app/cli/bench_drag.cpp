#include "bench_drag.h"

#include <algorithm>
#include <cstdio>

#include "render_state_model.h"
#include "voxray/io/statistics.h"

namespace voxray::cli {

DragReplay replayDrag(Raycaster& rc, const RenderParams& base, const glm::ivec2& view,
                      double minSpacingMm, Orbit orbit, int frames, double targetFps) {
  AdaptiveQuality adaptive(targetFps, dragPresetSetting());
  RenderParams b = base;
  Image image;
  DragReplay d;
  for (int i = 0; i < frames; ++i) {
    orbitCamera(b.camera, orbit, i, 180);
    const RenderParams p = planFrame(b, {}, view, true, minSpacingMm, &adaptive.setting());
    FrameStats stats;
    rc.rendererFor(p).render(p, image, &stats);
    d.ms.push_back(stats.totalMs);
    d.widths.push_back(p.width);
    // As RenderScheduler::onFrame reads the setting back from the frame.
    const int before = adaptive.changes();
    adaptive.record(stats.totalMs, dragSettingOf(p, view.x, minSpacingMm));
    if (adaptive.changes() != before)
      d.path.push_back({i, adaptive.setting().scale, adaptive.setting().stepVoxels});
  }
  return d;
}

void printDragReplay(const DragReplay& d, double targetFps) {
  const size_t first = std::min(d.firstAdapted(), d.ms.size());
  // Without a change every frame is the drag preset's own, and counts as adapted too.
  const std::vector<double> start(d.ms.begin(),
                                  d.path.empty() ? d.ms.end() : d.ms.begin() + long(first));
  const std::vector<double> adapted(d.ms.begin() + long(first), d.ms.end());
  const auto [lo, hi] = std::minmax_element(d.widths.begin() + long(first), d.widths.end());
  const double budget = 1000.0 / targetFps;
  const double within = double(std::count_if(adapted.begin(), adapted.end(),
                                             [&](double ms) { return ms <= budget; })) /
                        double(std::max<size_t>(adapted.size(), 1));
  const double median = quantile(adapted, 0.5);
  std::printf(
      "drag replay: %zu frames toward %.0f fps; the drag preset's own frames: median %.1f ms; "
      "%zu setting changes; the %zu frames after the first (widths %d-%d): median %.1f ms "
      "(%.1f fps), 90th percentile %.1f ms, %.0f %% within %.1f ms\n",
      d.ms.size(), targetFps, quantile(start, 0.5), d.path.size(), adapted.size(),
      adapted.empty() ? 0 : *lo, adapted.empty() ? 0 : *hi, median,
      median > 0 ? 1000.0 / median : 0.0, quantile(adapted, 0.9), 100.0 * within, budget);
  for (const DragChange& c : d.path)
    std::printf("  after frame %d: scale %.3f, step %.2f voxels\n", c.frame, c.scale, c.stepVoxels);
  std::fflush(stdout);
}

}  // namespace voxray::cli
