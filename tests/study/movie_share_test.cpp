// The workstation's movie export on the 3D view's device volume (issue 40 item 6): an orbit's
// frames rendered through the render worker (RenderWorker::renderOnDevice) upload no second
// copy of the volume and are byte for byte the frames of a raycaster of the export's own.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "movie.h"
#include "movie_export.h"
#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom.h"

using namespace voxray;

TEST(MovieShare, OrbitFramesOnTheViewsDeviceVolumeAreTheOwnContextsFrames) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(48));
  RenderWorker worker("cpu", {});
  worker.setVolume(volume);
  MoviePlan plan;
  plan.frames = 3;
  plan.params.width = 40;
  plan.params.height = 30;
  plan.params.mode = Mode::Dvr;
  plan.params.lighting = Lighting::Shadows;  // the light grid too: the view may have held it
  // The first call waits for the worker's upload of the view's volume (setVolume).
  const Image warm = worker.renderOnDevice(plan.params, volume.get());
  ASSERT_EQ(warm.width, 40);
  const int before = deviceVolumeUploads();
  MovieFrames shared(*volume, plan,
                     [&](const RenderParams& p) { return worker.renderOnDevice(p, volume.get()); });
  std::vector<Image> onView;
  for (int k = 0; k < shared.count(); ++k) onView.push_back(shared.frame(k));
  EXPECT_EQ(deviceVolumeUploads(), before);  // no second copy
  ClContext ctx("cpu");
  MovieFrames own(*volume, &ctx, plan);
  EXPECT_EQ(deviceVolumeUploads(), before + 1);  // what the export did before
  ASSERT_EQ(own.count(), 3);
  for (int k = 0; k < own.count(); ++k) {
    const Image mine = own.frame(k);
    ASSERT_EQ(mine.rgba.size(), onView[size_t(k)].rgba.size());
    EXPECT_TRUE(mine.rgba == onView[size_t(k)].rgba) << "frame " << k;
  }
  EXPECT_TRUE(onView[0].rgba != onView[1].rgba);  // a third of a turn apart
}

TEST(MovieShare, AVolumeNotOnTheDeviceIsAnErrorNotAnUpload) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(32));
  const Volume other = makeHeadPhantom(24);
  RenderWorker worker("cpu", {});
  worker.setVolume(volume);
  RenderParams p;
  p.width = 16;
  p.height = 12;
  worker.renderOnDevice(p, volume.get());
  const int before = deviceVolumeUploads();
  try {
    worker.renderOnDevice(p, &other);
    ADD_FAILURE() << "rendered a volume that is not on the device";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Device);
    EXPECT_NE(std::string(e.what()).find("export again"), std::string::npos) << e.what();
  }
  EXPECT_EQ(deviceVolumeUploads(), before);
}

namespace {

// This process's resident memory (VmRSS) in MiB.
double residentMiB() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0.0;
}

}  // namespace

// The figure of issue 40 item 6 on the 512x512x400 CT (docs/bench/make-ct400.sh) when
// VOXRAY_CT400_DIR names it: an orbit of 4 frames (CT-Bone dvr, 512x384) on the view's device
// volume, then on a context of its own as the export did before. Asserts what the small test
// does (no upload, the same frames) and prints the time and the resident memory each took.
TEST(MovieShare, Ct400FiguresWhenGiven) {
  const char* dir = std::getenv("VOXRAY_CT400_DIR");
  if (!dir) GTEST_SKIP() << "set VOXRAY_CT400_DIR to the 400-slice CT (make-ct400.sh)";
  auto volume = std::make_shared<const Volume>(loadVolume(dir));
  RenderWorker worker("cpu", {});
  worker.setVolume(volume);
  MoviePlan plan;
  plan.frames = 4;
  plan.params.width = 512;
  plan.params.height = 384;
  plan.params.mode = Mode::Dvr;
  plan.params.preset = "CT-Bone";
  worker.renderOnDevice(plan.params, volume.get());  // the view's frame: the volume is there
  using Clock = std::chrono::steady_clock;
  const int before = deviceVolumeUploads();
  double rss0 = residentMiB();
  auto t0 = Clock::now();
  MovieFrames shared(*volume, plan,
                     [&](const RenderParams& p) { return worker.renderOnDevice(p, volume.get()); });
  std::vector<Image> onView;
  for (int k = 0; k < shared.count(); ++k) onView.push_back(shared.frame(k));
  const double sharedS = std::chrono::duration<double>(Clock::now() - t0).count();
  const double sharedMiB = residentMiB() - rss0;
  EXPECT_EQ(deviceVolumeUploads(), before);
  rss0 = residentMiB();
  t0 = Clock::now();
  ClContext ctx("cpu");
  MovieFrames own(*volume, &ctx, plan);
  std::vector<Image> mine;
  for (int k = 0; k < own.count(); ++k) mine.push_back(own.frame(k));
  const double ownS = std::chrono::duration<double>(Clock::now() - t0).count();
  const double ownMiB = residentMiB() - rss0;
  EXPECT_EQ(deviceVolumeUploads(), before + 1);
  for (size_t k = 0; k < mine.size(); ++k) EXPECT_TRUE(mine[k].rgba == onView[k].rgba) << k;
  std::printf(
      "ct400 orbit of %d frames at 512x384: on the view's device volume %.2f s, +%.0f MiB "
      "resident; on a context of its own %.2f s, +%.0f MiB resident\n",
      shared.count(), sharedS, sharedMiB, ownS, ownMiB);
}
