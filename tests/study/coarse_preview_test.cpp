// Issue 38 part 1: a large study's first frame comes from a coarse level while its full
// volume uploads (Frame::coarse), then the full frame, the same as without a preview.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"

namespace voxray {
namespace {

// A CT-like ball: air, skin, a bone shell and brain in HU (stored = HU + 1024).
std::shared_ptr<Volume> ball(glm::ivec3 n) {
  auto v = std::make_shared<Volume>();
  v->dims = n;
  v->spacingMm = {0.5, 0.5, 1.0};
  v->intercept = -1024.0;
  v->voxels.resize(v->voxelCount());
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) {
        const double dx = (x - n.x / 2.0) / (0.45 * n.x), dy = (y - n.y / 2.0) / (0.42 * n.y),
                     dz = (z - n.z / 2.0) / (0.47 * n.z);
        const double r = dx * dx + dy * dy + dz * dz;
        v->voxels[v->index(x, y, z)] = int16_t(r < 0.77   ? 1064
                                               : r < 0.86 ? 2024
                                               : r < 1.0  ? 1024
                                                          : 24);
      }
  return v;
}

double psnrDb(const Image& a, const Image& b) {
  double se = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    se += d * d;
    ++n;
  }
  return se == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 * double(n) / se);
}

TEST(CoarsePreview, LargeStudyShowsTheCoarseFrameFirstThenTheUnchangedFullFrame) {
  std::mutex mutex;
  std::condition_variable arrived;
  std::vector<std::shared_ptr<const Frame>> frames;
  std::string error;
  RenderCallbacks cb;
  cb.frame = [&](std::shared_ptr<const Frame> f) {
    std::lock_guard lock(mutex);
    frames.push_back(std::move(f));
    arrived.notify_all();
  };
  cb.error = [&](const std::string& m, bool) {
    std::lock_guard lock(mutex);
    error = m;
    arrived.notify_all();
  };
  auto waitFor = [&](size_t count) {
    std::unique_lock lock(mutex);
    arrived.wait_for(lock, std::chrono::seconds(300),
                     [&] { return frames.size() >= count || !error.empty(); });
    ASSERT_EQ(error, "");
    ASSERT_GE(frames.size(), count);
  };
  RenderParams p;
  p.width = 160;
  p.height = 120;
  p.mode = Mode::Dvr;
  p.preset = "CT-Bone";
  p.camera.azimuthDeg = 30.0;
  const auto small = ball({64, 64, 32});   // below kCoarsePreviewBytes: no preview
  const auto big = ball({512, 512, 136});  // 68 MiB: previewed
  ASSERT_GE(big->byteSize(), kCoarsePreviewBytes);
  RenderWorker w("cpu", cb);
  w.setVolume(small);
  w.request(p, false);
  waitFor(1);
  EXPECT_FALSE(frames[0]->coarse);
  w.setVolume(big);
  w.request(p, false);
  waitFor(3);
  // The preview first, of the big volume, then its full frame.
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_TRUE(frames[1]->coarse);
  EXPECT_EQ(frames[1]->volume, big.get());
  EXPECT_FALSE(frames[2]->coarse);
  EXPECT_EQ(frames[2]->volume, big.get());
  // The full frame is the frame a raycaster renders without any preview, byte for byte.
  ClContext ctx("cpu");
  Raycaster rc(ctx, *big);
  Image alone;
  rc.render(p, alone);
  EXPECT_EQ(frames[2]->image.rgba, alone.rgba);
  // 4x box mean of a 0.5 mm ball: measured 27.2 dB here; 25 dB (RMS 14 levels) leaves room for
  // another PoCL's rounding, and a preview in the wrong place or scale falls far below.
  const double db = psnrDb(frames[1]->image, frames[2]->image);
  std::printf("coarse preview PSNR %.2f dB against the full frame\n", db);
  EXPECT_GT(db, 25.0);
}

}  // namespace
}  // namespace voxray
