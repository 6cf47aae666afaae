// Slab images off the GUI thread (SlabRenderer): request() returns long before the image,
// the image is renderPlane's, pixel for pixel, and the newest request wins.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>

#include <gtest/gtest.h>

#include "slab_render.h"
#include "slice_geometry.h"
#include "voxray/io/volume.h"

using namespace voxray;

namespace {

// 256 x 256 x 160 of 1 mm voxels with a value ramp, large enough that a 40 mm slab takes
// a measurable time on the CPU.
std::shared_ptr<const Volume> ramp() {
  auto v = std::make_shared<Volume>();
  v->dims = {256, 256, 160};
  v->spacingMm = {1.0, 1.0, 1.0};
  v->modality = "CT";
  v->voxels.resize(v->voxelCount());
  for (int k = 0; k < v->dims.z; ++k)
    for (int j = 0; j < v->dims.y; ++j)
      for (int i = 0; i < v->dims.x; ++i)
        v->voxels[v->index(i, j, k)] = int16_t((i * 7 + j * 3 + k * 11) % 2000 - 1000);
  return v;
}

// Events the "GUI thread" (this test) runs when it chooses, as a queued connection would.
struct EventQueue {
  std::mutex mutex;
  std::condition_variable arrived;
  std::deque<BackgroundTask::Event> events;
  BackgroundTask::Post post() {
    return [this](BackgroundTask::Event e) {
      std::lock_guard lock(mutex);
      events.push_back(std::move(e));
      arrived.notify_all();
    };
  }
  // Runs what has arrived, waiting up to TIMEOUT for something to.
  void drain(std::chrono::milliseconds timeout) {
    std::deque<BackgroundTask::Event> now;
    {
      std::unique_lock lock(mutex);
      arrived.wait_for(lock, timeout, [&] { return !events.empty(); });
      now.swap(events);
    }
    for (auto& e : now) e();
  }
};

bool samePixels(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

}  // namespace

TEST(SlabRender, RequestReturnsBeforeTheImageAndNewestWins) {
  const auto v = ramp();
  const SliceAxes axes = sliceAxes(v->direction, Orientation::Axial);
  const PlaneGrid plane = slicePlane(*v, axes, 80);
  const WindowLevel wl{2000, 0};
  const Slab older{40.0, SlabMode::Mip}, newer{30.0, SlabMode::MinIp};

  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  const Image expected = renderPlane(*v, plane, wl, Interp::Linear, newer);
  const auto renderTime = Clock::now() - t0;
  ASSERT_FALSE(samePixels(expected, renderPlane(*v, plane, wl, Interp::Linear, older)));

  EventQueue gui;
  std::vector<Image> shown;
  SlabRenderer slabs([&](Image image) { shown.push_back(std::move(image)); }, gui.post());
  t0 = Clock::now();
  slabs.request({v, plane, wl, Interp::Linear, older});
  slabs.request({v, plane, wl, Interp::Linear, newer});  // replaces the first
  const auto requestTime = Clock::now() - t0;
  // Both requests returned in a small part of one render: the caller's thread never waits.
  EXPECT_LT(requestTime * 4, renderTime);
  EXPECT_TRUE(shown.empty());

  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (shown.empty() && Clock::now() < deadline) gui.drain(std::chrono::milliseconds(50));
  gui.drain(std::chrono::milliseconds(300));  // a stale image arriving late is dropped too
  ASSERT_EQ(shown.size(), 1U);
  EXPECT_TRUE(samePixels(shown.front(), expected));
}

TEST(SlabRender, DroppedRequestShowsNothing) {
  const auto v = ramp();
  const SliceAxes axes = sliceAxes(v->direction, Orientation::Coronal);
  EventQueue gui;
  int shown = 0;
  SlabRenderer slabs([&](Image) { ++shown; }, gui.post());
  slabs.request({v, slicePlane(*v, axes, 100), WindowLevel{400, 40}, Interp::Nearest,
                 Slab{20.0, SlabMode::Mean}});
  slabs.drop();  // the view went thin before the slab arrived
  for (int i = 0; i < 20; ++i) gui.drain(std::chrono::milliseconds(50));
  EXPECT_EQ(shown, 0);
}
