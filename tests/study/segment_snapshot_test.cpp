// The segmentation's shared snapshot (copy on write, SegmentationModel::snapshot): what the
// statistics refresh and the 3D view's copy take on the GUI thread instead of a copy of the
// label map. Values asserted: a snapshot never changes, the model's edit goes to its own copy
// while one is held and to the same map when none is. Times printed, not asserted (a shared
// machine): the GUI thread's part of a statistics refresh on a CT-sized map, before (a copy)
// and after (the snapshot).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "segmentation_model.h"

namespace voxray {
namespace {

template <class F>
double medianMs(int runs, F&& f) {
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

TEST(SegmentSnapshot, ASnapshotIsSharedUntilTheNextEditAndNeverChanges) {
  Volume v;  // the grid alone: the model's label map needs no voxels
  v.dims = {64, 64, 40};
  SegmentationModel m;
  m.reset(v);
  const uint8_t a = m.addSegment("A", {1, 0, 0});
  m.paintSphere({32, 32, 20}, 8.0, a);
  const Segmentation* before = &m.segmentation();
  {
    auto snap = m.snapshot();
    EXPECT_EQ(snap.get(), before);  // shared: no copy
    const std::vector<uint8_t> labels = snap->labels;
    m.paintSphere({10, 10, 10}, 4.0, a);  // held: the model copies, then edits its copy
    EXPECT_NE(&m.segmentation(), snap.get());
    EXPECT_EQ(snap->labels, labels);  // the snapshot as taken
    EXPECT_NE(m.segmentation().labels, labels);
  }
  const Segmentation* owned = &m.segmentation();
  m.paintSphere({50, 50, 30}, 4.0, a);  // none held: edited in place
  EXPECT_EQ(&m.segmentation(), owned);
  m.undo();
  EXPECT_EQ(&m.segmentation(), owned);
}

TEST(SegmentSnapshot, GuiThreadTimeOfAStatisticsRefreshOnACtSizedMap) {
  Volume v;
  v.dims = {512, 512, 400};
  v.spacingMm = {0.7, 0.7, 1.0};
  SegmentationModel m;
  m.reset(v);
  const uint8_t a = m.addSegment("Bone", {1, 1, 1});
  m.paintSphere({180, 180, 200}, 80.0, a);
  // Before: the panel copied the segmentation for the pool (make_shared of a copy).
  const double copyMs = medianMs(5, [&] {
    auto copy = std::make_shared<const Segmentation>(m.segmentation());
    ASSERT_EQ(copy->labels.size(), size_t(512) * 512 * 400);
  });
  // After: the snapshot.
  const double snapshotMs = medianMs(5, [&] {
    auto snap = m.snapshot();
    ASSERT_EQ(snap->labels.size(), size_t(512) * 512 * 400);
  });
  // The cost moves to the first edit made while a count still holds its snapshot.
  double detachMs = 0.0;
  {
    auto held = m.snapshot();
    const auto t0 = std::chrono::steady_clock::now();
    m.paintSphere({300, 300, 200}, 5.0, a);
    detachMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  const double editMs = medianMs(5, [&] { m.paintSphere({300, 300, 200}, 5.0, a); });
  std::printf(
      "512x512x400 label map, GUI thread: statistics refresh before (copy) %.2f ms, after "
      "(snapshot) %.4f ms (medians of 5); a 5 mm paint dab while a count holds the snapshot "
      "%.2f ms, without %.2f ms\n",
      copyMs, snapshotMs, detachMs, editMs);
  SUCCEED();
}

}  // namespace
}  // namespace voxray
