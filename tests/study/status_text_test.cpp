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

TEST(StatusText, RateCountsOnlyFramesThatFollowEachOther) {
  FrameRateMeter m;
  EXPECT_EQ(m.frameAt(10.0), 0.0);  // the first frame: no rate
  EXPECT_NEAR(m.frameAt(10.1), 10.0, 1e-9);
  double steady = m.frameAt(10.2);
  EXPECT_NEAR(steady, 10.0, 1e-9);
  // A 32 ms frame after half a minute of idling: no rate, not "0.0 fps · 32 ms".
  double afterIdle = m.frameAt(40.0);
  EXPECT_EQ(afterIdle, 0.0);
  EXPECT_EQ(formatFrameStats({true, afterIdle, 32.0, false}), "32 ms");
  // Dragging again: the rate is that of the new frames alone.
  EXPECT_NEAR(m.frameAt(40.05), 20.0, 1e-9);
  EXPECT_NEAR(m.frameAt(40.10), 20.0, 1e-6);
}
