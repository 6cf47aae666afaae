// Figures, not a timed test (issue 36's closing note): how long switching the time point of
// a 4D series takes in the slice views and in the 3D view's next frame. Skipped unless
// VOXRAY_4D_DIR names a series (voxray-cli make-phantom beating-sphere DIR --dims ...); run
//   VOXRAY_4D_DIR=DIR voxray_study_tests --gtest_also_run_disabled_tests \
//     --gtest_filter='*TimeSwitchFigures*'
// and it prints medians. Nothing is asserted about time: the machine is shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "app_models.h"
#include "render_worker.h"
#include "slice_image.h"
#include "study_state.h"
#include "time_series.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

TEST(DISABLED_TimeSwitchFigures, SliceViewsAnd3dNextFrame) {
  const char* dir = std::getenv("VOXRAY_4D_DIR");
  if (!dir) GTEST_SKIP() << "set VOXRAY_4D_DIR to a 4D series";
  auto t0 = Clock::now();
  VolumeSeries series;
  for (Volume& v : loadVolumeSeries(dir))
    series.push_back(std::make_shared<const Volume>(std::move(v)));
  const double loadMs = msSince(t0);
  size_t bytes = 0;
  for (const auto& v : series) bytes += v->byteSize();
  const Volume& v0 = *series[0];
  std::printf("series: %zu time points of %dx%dx%d, %.2f GiB in memory, loaded in %.1f s\n",
              series.size(), v0.dims.x, v0.dims.y, v0.dims.z, double(bytes) / (1 << 30),
              loadMs / 1000.0);
  ASSERT_GE(series.size(), 2u);

  AppModels m;
  openStudy(m, series, "4d", {}, 0);
  const int n = int(series.size());
  // The slice views: each view resamples its plane of the new time point (SliceView::rebuild).
  double sumOfViews = 0.0;
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal}) {
    const SliceAxes axes = sliceAxes(v0.direction, o);
    const PlaneGrid plane = viewPlane(v0, axes, m.crosshair.centre(), glm::dmat3(1.0));
    std::vector<double> ms;
    for (int round = 0; round < 3; ++round)
      for (int t = 0; t < n; ++t) {
        const auto s = Clock::now();
        m.document.setTimePoint(t);
        const Image img =
            renderPlane(*m.document.volume(), plane, m.windowLevel.value(), Interp::Linear);
        ms.push_back(msSince(s));
        ASSERT_EQ(img.width, plane.size.x);
      }
    std::printf("slice view %d (%dx%d px): median %.2f ms per time point switch (%zu switches)\n",
                int(o), plane.size.x, plane.size.y, median(ms), ms.size());
    sumOfViews += median(ms);
  }
  std::printf("all three slice views: %.2f ms\n", sumOfViews);

  // The 3D view: the render worker (PoCL CPU) with the drag frame the view asks for.
  std::mutex mutex;
  std::condition_variable cv;
  int frames = 0;
  std::string error;
  RenderCallbacks cb;
  cb.frame = [&](std::shared_ptr<const Frame>) {
    std::lock_guard lock(mutex);
    ++frames;
    cv.notify_all();
  };
  cb.error = [&](const std::string& e, bool) {
    std::lock_guard lock(mutex);
    error = e;
    ++frames;
    cv.notify_all();
  };
  RenderWorker worker("cpu", cb);
  const glm::ivec2 size{720, 480};  // one view of the 2x2 grid at 1920x1080
  // The sphere's surface (300 HU inside, -50 outside): the CT dvr preset leaves both clear,
  // and a frame of empty space would time nothing.
  m.render.update(kAppearance, [](RenderParams& r) {
    r.mode = Mode::Iso;
    r.isoLo = 100.0;
  });
  const DragSetting drag = dragPresetSetting();
  const RenderParams p =
      planFrame(m.render.params(), m.render.quality(), size, true, v0.minSpacingMm(), &drag);
  auto frameAfter = [&](const std::function<void()>& ask) {
    int before;
    {
      std::lock_guard lock(mutex);
      before = frames;
    }
    const auto s = Clock::now();
    ask();
    std::unique_lock lock(mutex);
    cv.wait(lock, [&] { return frames > before; });
    return msSince(s);
  };
  const double firstMs = frameAfter([&] {
    worker.setVolume(series[0]);
    worker.request(p, true);
  });
  std::printf("3D: %dx%d drag frame (%s), first frame with upload and kernel build %.0f ms\n",
              p.width, p.height, toString(p.mode), firstMs);
  ASSERT_TRUE(error.empty()) << error;
  std::vector<double> same, firstVisit, resident;
  for (int i = 0; i < 9; ++i) same.push_back(frameAfter([&] { worker.request(p, true); }));
  for (int t = 1; t < n; ++t)
    firstVisit.push_back(frameAfter([&] {
      worker.setVolume(series[size_t(t)], true);
      worker.request(p, true);
    }));
  for (int round = 0; round < 2; ++round)
    for (int t = 0; t < n; ++t)
      resident.push_back(frameAfter([&] {
        worker.setVolume(series[size_t(t)], true);
        worker.request(p, true);
      }));
  ASSERT_TRUE(error.empty()) << error;
  std::printf("3D drag frame, same time point: median %.1f ms\n", median(same));
  std::printf("3D next frame after a switch, first visit (upload): median %.1f ms\n",
              median(firstVisit));
  std::printf("3D next frame after a switch, resident: median %.1f ms (%zu switches)\n",
              median(resident), resident.size());

  {  // Where a first visit's time goes: the upload (Raycaster) or the first frame on it.
    ClContext ctx("cpu");
    Raycaster warm(ctx, *series[0]);
    Image img;
    warm.rendererFor(p).render(p, img);
    auto s = Clock::now();
    Raycaster fresh(ctx, *series[1]);
    const double uploadMs = msSince(s);
    s = Clock::now();
    fresh.rendererFor(p).render(p, img);
    const double firstMs = msSince(s);
    s = Clock::now();
    fresh.rendererFor(p).render(p, img);
    std::printf("3D first visit: upload %.1f ms, first frame on it %.1f ms, next %.1f ms\n",
                uploadMs, firstMs, msSince(s));
  }

  // As the workstation opens a series: the other time points uploaded ahead while idle.
  RenderWorker ahead("cpu", cb);
  t0 = Clock::now();
  frameAfter([&] {
    ahead.setVolume(series[0]);
    ahead.preload(series);
    ahead.request(p, true);
  });
  // The uploads ahead take about the first-visit time each; a frame asked for meanwhile
  // waits for the one in progress (measured here as the frame right after the first).
  const double during = frameAfter([&] { ahead.request(p, true); });
  std::this_thread::sleep_for(
      std::chrono::duration<double, std::milli>(1.5 * median(firstVisit) * double(n) + 1000.0));
  std::vector<double> preloaded;
  for (int t = 1; t < n; ++t)
    preloaded.push_back(frameAfter([&] {
      ahead.setVolume(series[size_t(t)], true);
      ahead.request(p, true);
    }));
  ASSERT_TRUE(error.empty()) << error;
  std::printf("3D drag frame while uploading ahead: %.1f ms\n", during);
  std::printf(
      "3D next frame after a switch, first visit after uploading ahead: median %.1f ms, "
      "max %.1f ms\n",
      median(preloaded), *std::max_element(preloaded.begin(), preloaded.end()));
}

}  // namespace
}  // namespace voxray
