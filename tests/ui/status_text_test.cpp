// What the status bar and the window title say about frames and the device.
#include <gtest/gtest.h>

#include "status_text.h"

using namespace voxray::ui;

TEST(StatusText, FrameStats) {
  EXPECT_EQ(formatFrameStats({}), "no frame yet");
  EXPECT_EQ(formatFrameStats({true, 0.0, 14632.0, false}), "14632 ms");
  EXPECT_EQ(formatFrameStats({true, 12.46, 80.4, false}), "12.5 fps · 80 ms");
  EXPECT_EQ(formatFrameStats({true, 30.0, 33.3, true}), "30.0 fps · 33 ms (interactive)");
}

TEST(StatusText, TitleHasNameFpsAndDevice) {
  EXPECT_EQ(formatWindowTitle("", {}, ""), "Voxray");
  EXPECT_EQ(formatWindowTitle("CThead", {}, ""), "CThead — Voxray");
  EXPECT_EQ(formatWindowTitle("CThead", {true, 24.0, 41.0, true}, "NVIDIA H100"),
            "CThead — 24.0 fps · 41 ms — NVIDIA H100 — Voxray");
  EXPECT_EQ(formatWindowTitle("", {}, "cpu"), "cpu — Voxray");
}
