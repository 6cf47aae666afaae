// What the status bar and the window title say about frames.
#include <gtest/gtest.h>

#include "status_text.h"

using namespace voxray;

TEST(StatusText, FrameStats) {
  EXPECT_EQ(formatFrameStats({}), "no frame yet");
  EXPECT_EQ(formatFrameStats({true, 0.0, 14632.0, false}), "14632 ms");
  EXPECT_EQ(formatFrameStats({true, 12.46, 80.4, false}), "12.5 fps · 80 ms");
  EXPECT_EQ(formatFrameStats({true, 30.0, 33.3, true}), "30.0 fps · 33 ms (interactive)");
}

TEST(StatusText, TitleIsTheDocumentNameOnly) {
  // Fixed while rendering: no frame rate, no device (the status bar has both).
  EXPECT_EQ(formatWindowTitle(""), "Voxray");
  EXPECT_EQ(formatWindowTitle("CThead"), "CThead — Voxray");
}

TEST(StatusText, RateCountsOnlyDragFramesThatFollowEachOther) {
  FrameRateMeter m;
  // A drag at 10 fps: no rate until five of its frames, then frames over their time span.
  for (int k = 0; k < 4; ++k) EXPECT_EQ(m.frameAt(10.0 + 0.1 * k, true), 0.0) << k;
  EXPECT_NEAR(m.frameAt(10.4, true), 10.0, 1e-9);
  EXPECT_NEAR(m.frameAt(10.5, true), 10.0, 1e-9);
  // The span covers the last ten frames: an early slow frame leaves the rate.
  FrameRateMeter slowStart;
  slowStart.frameAt(0.0, true);
  for (int k = 1; k <= 10; ++k) slowStart.frameAt(0.5 + 0.05 * k, true);
  EXPECT_NEAR(slowStart.frameAt(1.05, true), 20.0, 1e-9);
  // Drag frames after half a minute of idling start afresh.
  EXPECT_EQ(m.frameAt(40.0, true), 0.0);
  for (int k = 1; k < 4; ++k) EXPECT_EQ(m.frameAt(40.0 + 0.05 * k, true), 0.0) << k;
  EXPECT_NEAR(m.frameAt(40.2, true), 20.0, 1e-6);
}

TEST(StatusText, AStillFrameShowsItsTimeAndNoRate) {
  // Issue 41 item 5: the sharp frame 3 ms after the last drag frame, and progressive passes
  // close behind each other, read "381.6 fps · 72 ms" and "267.6 fps · 323 ms".
  FrameRateMeter m;
  for (int k = 0; k < 6; ++k) m.frameAt(0.05 * k, true);
  const double still = m.frameAt(0.253, false);
  EXPECT_EQ(still, 0.0);
  EXPECT_EQ(formatFrameStats({true, still, 72.0, false}), "72 ms");
  EXPECT_EQ(m.frameAt(0.256, false), 0.0);  // a progressive pass right behind it
  EXPECT_EQ(formatFrameStats({true, 0.0, 14632.0, false}), "14632 ms");
  // The next drag counts its own frames only.
  EXPECT_EQ(m.frameAt(0.30, true), 0.0);
}
