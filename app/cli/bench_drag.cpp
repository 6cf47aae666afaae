#include "bench_drag.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "clip_box_math.h"
#include "render_state_model.h"
#include "voxray/io/error.h"
#include "voxray/io/statistics.h"
#include "voxray/lab/accuracy.h"

namespace voxray::cli {

DragOption parseDragOption(const std::string& text) {
  DragOption o;
  std::string count = text;
  if (text.rfind("clip", 0) == 0) {
    o.motion = DragMotion::ClipFace;
    o.frames = DragOption::kClipDragFrames;
    count = text.size() > 5 && text[4] == ':' ? text.substr(5) : text == "clip" ? "" : "x";
  }
  if (!count.empty()) {
    char* end = nullptr;
    const long n = std::strtol(count.c_str(), &end, 10);
    if (*end != '\0' || n < 1 || n > 100000)
      throw inputError(
          "--drag: expected a frame count 1..100000 (a rotation), clip or clip:N "
          "(a clip-box drag), got '" +
          text + "'");
    o.frames = int(n);
  }
  return o;
}

ClipBox clipDragBox(int i, int frames) {
  // A triangle wave: in to half the extent over the first half of the frames, back out over
  // the second, as a user drags a face in to look and lets it back.
  const double half = std::max(1.0, std::floor(frames / 2.0));
  const double t = i <= half ? i / half : std::max(0.0, (frames - 1 - i) / half);
  ClipBox box;
  setClipFace(box, 2, 0.5 * t);
  return box;
}

DragReplay replayDrag(Raycaster& rc, const RenderParams& base, const glm::ivec2& view,
                      double minSpacingMm, Orbit orbit, int frames, double targetFps,
                      DragMotion motion) {
  AdaptiveQuality adaptive(targetFps, dragPresetSetting());
  RenderParams b = base;
  Image image;
  DragReplay d;
  d.motion = motion;
  // The drag's first frame may classify (the drag preset's own step): count from the second
  // frame on, once the tables stand for this classification.
  int classifiedBefore = 0, builtBefore = 0;
  const bool lit = base.lighting == Lighting::Shadows || base.lighting == Lighting::Ao;
  std::vector<RenderParams> planned;
  if (lit) {
    // The grid of the view at rest before the drag, as the workstation has it when a drag
    // starts (the first drag frame would otherwise build it).
    RenderParams still = planFrame(b, {}, view, false, minSpacingMm);
    if (motion == DragMotion::Rotation) orbitCamera(still.camera, orbit, 0, 180);
    rc.render(still, image);
  }
  rc.holdLightGrid(lit);
  for (int i = 0; i < frames; ++i) {
    if (motion == DragMotion::Rotation)
      orbitCamera(b.camera, orbit, i, 180);
    else
      b.clip = clipDragBox(i, frames);
    const RenderParams p = planFrame(b, {}, view, true, minSpacingMm, &adaptive.setting());
    FrameStats stats;
    rc.rendererFor(p).render(p, image, &stats);
    if (i == 0) classifiedBefore = rc.classifications(), builtBefore = rc.lightingBuilds();
    d.ms.push_back(stats.totalMs);
    d.widths.push_back(p.width);
    if (lit) {
      RenderParams phong = p;
      phong.lighting = Lighting::Phong;  // builds nothing and leaves the held grid as it is
      FrameStats ps;
      rc.render(phong, image, &ps);
      d.phongMs.push_back(ps.totalMs);
      planned.push_back(p);
    }
    // As RenderScheduler::onFrame reads the setting back from the frame.
    const int before = adaptive.changes();
    adaptive.record(stats.totalMs, dragSettingOf(p, view.x, minSpacingMm));
    if (adaptive.changes() != before)
      d.path.push_back({i, adaptive.setting().scale, adaptive.setting().stepVoxels});
  }
  d.classifications = rc.classifications() - classifiedBefore;
  d.lightingBuilds = rc.lightingBuilds() - builtBefore;
  rc.holdLightGrid(false);
  if (lit && base.lighting == Lighting::Shadows && motion == DragMotion::Rotation) {
    // Each sampled frame held on the grid of frame 0's light, then rebuilt for its own: 10,
    // 30 and 44 degrees into the drag (the raycaster rebuilds a held grid past 45 degrees of
    // the light's turn, so 44 is about the worst a drag shows).
    Image held, fresh, phong;
    for (int i : {5, 15, 22}) {
      if (i >= int(planned.size())) break;
      const RenderParams& p = planned[size_t(i)];
      rc.render(planned[0], image);  // the grid of the drag's start
      rc.holdLightGrid(true);
      rc.render(p, held);
      rc.holdLightGrid(false);
      rc.render(p, fresh);
      RenderParams ph = p;
      ph.lighting = Lighting::Phong;
      rc.render(ph, phong);
      const FloatImage converged = toFloatImage(fresh);
      d.heldErrors.push_back({2.0 * i, compareImages(toFloatImage(held), converged).psnrDb,
                              compareImages(toFloatImage(phong), converged).psnrDb});
    }
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
      "%s replay: %zu frames toward %.0f fps; the drag preset's own frames: median %.1f ms; "
      "%zu setting changes; the %zu frames after the first (widths %d-%d): median %.1f ms "
      "(%.1f fps), 90th percentile %.1f ms, %.0f %% within %.1f ms\n",
      d.motion == DragMotion::ClipFace ? "clip drag" : "drag", d.ms.size(), targetFps,
      quantile(start, 0.5), d.path.size(), adapted.size(), adapted.empty() ? 0 : *lo,
      adapted.empty() ? 0 : *hi, median, median > 0 ? 1000.0 / median : 0.0, quantile(adapted, 0.9),
      100.0 * within, budget);
  std::printf("  empty-space classifications after the first frame: %d (%zu setting changes)\n",
              d.classifications, d.path.size());
  if (!d.phongMs.empty()) {
    const std::vector<double> phong(d.phongMs.begin() + long(first), d.phongMs.end());
    std::vector<double> ratio;
    for (size_t i = first; i < d.ms.size() && i < d.phongMs.size(); ++i)
      ratio.push_back(d.ms[i] / std::max(d.phongMs[i], 1e-9));
    std::printf(
        "  light grid held: %d builds after the first frame; the same %zu frames in phong: "
        "median %.1f ms; lit / phong frame by frame: median %.2f x, 90th percentile %.2f x\n",
        d.lightingBuilds, phong.size(), quantile(phong, 0.5), quantile(ratio, 0.5),
        quantile(ratio, 0.9));
  }
  for (const HeldGridError& e : d.heldErrors)
    std::printf(
        "  held grid %.0f degrees from its light: PSNR %.1f dB against the rebuilt grid's frame "
        "(phong, no shadows: %.1f dB)\n",
        e.degrees, e.psnrDb, e.phongPsnrDb);
  for (const DragChange& c : d.path)
    std::printf("  after frame %d: scale %.3f, step %.2f voxels\n", c.frame, c.scale, c.stepVoxels);
  std::fflush(stdout);
}

}  // namespace voxray::cli
