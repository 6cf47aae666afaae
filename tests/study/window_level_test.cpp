#include <gtest/gtest.h>

#include "window_level.h"

using namespace voxray;

TEST(WindowLevel, RampEndsAndCentre) {
  WindowLevel brain{80, 40};
  EXPECT_EQ(mapToGrey(0, brain), 0);     // level - width/2
  EXPECT_EQ(mapToGrey(80, brain), 255);  // level + width/2
  EXPECT_EQ(mapToGrey(40, brain), 128);  // the level is mid-grey
  EXPECT_EQ(mapToGrey(-1000, brain), 0);
  EXPECT_EQ(mapToGrey(3000, brain), 255);
  WindowLevel lung{1500, -600};
  EXPECT_EQ(mapToGrey(-1350, lung), 0);
  EXPECT_EQ(mapToGrey(150, lung), 255);
  EXPECT_EQ(mapToGrey(-975, lung), 64);  // a quarter of the way up
}

TEST(WindowLevel, PresetsHaveTheRadiologyValues) {
  WindowLevelModel m;
  int notified = 0;
  m.changed.connect([&] { ++notified; });
  struct Expect {
    const char* name;
    double w, l;
  };
  for (Expect e :
       {Expect{"Brain", 80, 40}, Expect{"Subdural", 215, 75}, Expect{"Stroke", 40, 40},
        Expect{"Lung", 1500, -600}, Expect{"Mediastinum", 350, 50}, Expect{"Abdomen", 400, 50},
        Expect{"Liver", 150, 30}, Expect{"Bone", 1800, 400}}) {
    ASSERT_TRUE(m.applyPreset(e.name)) << e.name;
    EXPECT_EQ(m.value().width, e.w) << e.name;
    EXPECT_EQ(m.value().level, e.l) << e.name;
  }
  EXPECT_EQ(notified, 8);
  EXPECT_FALSE(m.applyPreset("Nonsense"));
  m.set(m.value());  // no change: no notification
  EXPECT_EQ(notified, 8);
}

TEST(WindowLevel, DragRightWidensDownRaisesLevel) {
  WindowLevel start{400, 40};
  WindowLevel wl = dragWindowLevel(start, 100, 0);
  EXPECT_DOUBLE_EQ(wl.width, 600);  // 2 HU per pixel at width 400
  EXPECT_DOUBLE_EQ(wl.level, 40);
  wl = dragWindowLevel(start, 0, 50);
  EXPECT_DOUBLE_EQ(wl.level, 140);
  wl = dragWindowLevel(start, -10000, 0);
  EXPECT_GE(wl.width, 1.0);  // never zero or negative
}
