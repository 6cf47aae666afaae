// Shaping the transfer function by dragging in the 3D view (issue 35): exact HU, stretch and
// opacity factors for a drag, in dvr, iso and mip.
#include <gtest/gtest.h>

#include "tf_drag.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {
namespace {

RenderParams rampParams() {
  RenderParams p;
  p.mode = Mode::Dvr;
  p.transferFunction = {{0.0, {1, 1, 1, 0.0}}, {200.0, {1, 1, 1, 0.2}}, {400.0, {1, 1, 1, 0.4}}};
  return p;
}

}  // namespace

TEST(TfDrag, UpMovesTheTableAlongHuAndSidewaysStretchesItAboutWhatShows) {
  // A tenth of the view up with 2000 HU per view height: +200 HU.
  RenderParams up = dragTransferFunction(rampParams(), {0.0, 0.1}, 2000.0, false);
  ASSERT_EQ(up.transferFunction.size(), 3u);
  EXPECT_DOUBLE_EQ(up.transferFunction[0].hu, 200.0);
  EXPECT_DOUBLE_EQ(up.transferFunction[2].hu, 600.0);
  EXPECT_EQ(up.transferFunction[1].rgba, rampParams().transferFunction[1].rgba);
  // Half the view right: twice as wide about the middle of the visible range (300 HU).
  RenderParams wide = dragTransferFunction(rampParams(), {0.5, 0.0}, 2000.0, false);
  EXPECT_DOUBLE_EQ(wide.transferFunction[0].hu, -300.0);
  EXPECT_DOUBLE_EQ(wide.transferFunction[1].hu, 100.0);
  EXPECT_DOUBLE_EQ(wide.transferFunction[2].hu, 500.0);
  // With the opacity modifier a third of the view up doubles the opacity, clamped to 1.
  RenderParams more = dragTransferFunction(rampParams(), {0.3, 1.0 / 3.0}, 2000.0, true);
  EXPECT_DOUBLE_EQ(more.transferFunction[1].hu, 200.0);
  EXPECT_NEAR(more.transferFunction[2].rgba.a, 0.8, 1e-12);
  RenderParams most = dragTransferFunction(rampParams(), {0.0, 1.0}, 2000.0, true);
  EXPECT_DOUBLE_EQ(most.transferFunction[2].rgba.a, 1.0);
}

TEST(TfDrag, APresetIsDraggedAsTheTableOnScreen) {
  RenderParams p;
  applyPreset(p, findPreset("CT-Bone"));
  p.presetShiftHu = 50.0;
  RenderParams moved = dragTransferFunction(p, {0.0, -0.05}, 4000.0, false);  // -200 HU
  EXPECT_TRUE(moved.preset.empty());
  EXPECT_EQ(moved.presetShiftHu, 0.0);
  const auto& preset = findPreset("CT-Bone").tf.points;
  ASSERT_EQ(moved.transferFunction.size(), preset.size());
  for (size_t i = 0; i < preset.size(); ++i)
    EXPECT_DOUBLE_EQ(moved.transferFunction[i].hu, preset[i].hu + 50.0 - 200.0) << i;
}

TEST(TfDrag, IsoMovesTheThresholdAndMipTheWindow) {
  RenderParams iso;
  iso.mode = Mode::Iso;
  iso.isoLo = 400.0;
  EXPECT_DOUBLE_EQ(dragTransferFunction(iso, {0.7, -0.1}, 3000.0, false).isoLo, 100.0);
  RenderParams mip;
  mip.mode = Mode::Mip;
  mip.windowWidth = 800.0;
  mip.windowLevel = 100.0;
  RenderParams m = dragTransferFunction(mip, {-0.5, 0.2}, 3000.0, false);
  EXPECT_DOUBLE_EQ(m.windowWidth, 400.0);
  EXPECT_DOUBLE_EQ(m.windowLevel, 700.0);
  mip.windowWidth = 0.0;  // the volume's range: the drag starts from the span
  EXPECT_DOUBLE_EQ(dragTransferFunction(mip, {0.5, 0.0}, 3000.0, false).windowWidth, 6000.0);
}

}  // namespace voxray
