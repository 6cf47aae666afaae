// Issue 41 item 2: an MR (or any volume whose values are not HU) opened with an HU look —
// the iso threshold 400 the user keeps as a preference — showed an empty 3D view. It opens
// with a look from its own histogram; the user's HU look comes back with the next CT.
#include <gtest/gtest.h>

#include <filesystem>

#include "study_state.h"
#include "value_look.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/phantom.h"
#include "voxray/io/raw_import.h"

using namespace voxray;

namespace {

// An MR-like head: background 0 with noise-free air, a "brain" ball of value 200 and a
// thin "skin" shell of 280, modality MR: every value far below 400.
std::shared_ptr<const Volume> mrBall() {
  Volume v;
  v.dims = {48, 48, 48};
  v.spacingMm = {1.0, 1.0, 1.0};
  v.modality = "MR";
  v.unit = "";
  v.voxels.assign(size_t(48) * 48 * 48, 0);
  for (int z = 0; z < 48; ++z)
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x) {
        const double r = glm::length(glm::dvec3(x, y, z) - 23.5);
        const int16_t value = r < 16.0 ? 200 : r < 18.0 ? 280 : 0;
        v.voxels[(size_t(z) * 48 + y) * 48 + x] = value;
      }
  return std::make_shared<const Volume>(std::move(v));
}

// How many pixels of a 3D frame of P differ from the background.
int coveredPixels(const Volume& v, RenderParams p) {
  p.width = 64;
  p.height = 64;
  ClContext ctx("cpu");
  Raycaster rc(ctx, v);
  const Image img = rc.render(p);
  const glm::dvec3 bg = p.background * 255.0;
  int covered = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    if (std::abs(img.rgba[i] - bg.r) > 8 || std::abs(img.rgba[i + 1] - bg.g) > 8 ||
        std::abs(img.rgba[i + 2] - bg.b) > 8)
      ++covered;
  return covered;
}

}  // namespace

TEST(ValueLook, PercentilesOfTheVolumesOwnValues) {
  const auto mr = mrBall();
  const ValueLook look = valueLook(*mr);
  // Most voxels are air (0); the 99.5th percentile lies in the shell (280).
  EXPECT_EQ(look.low, 0.0);
  EXPECT_EQ(look.high, 280.0);
  EXPECT_EQ(look.threshold, 70.0);
}

TEST(ValueLook, AnMrOpensWithAVisibleSurfaceAndTheCtLookComesBack) {
  AppModels m;
  openStudy(m, std::make_shared<const Volume>(makeHeadPhantom(32)), "ct");
  m.render.update(kAppearance, [](RenderParams& p) {
    p.mode = Mode::Iso;
    p.isoLo = 400.0;
  });
  // Before the fix the MR opened at iso 400: no voxel reaches it, not one pixel covered.
  const auto mr = mrBall();
  openStudy(m, mr, "mr");
  EXPECT_EQ(m.render.params().isoLo, 70.0);
  EXPECT_EQ(m.render.params().mode, Mode::Iso);  // the user's mode stays
  // The ball (radius 18 of a 48-voxel box the camera frames whole) covers about 13 % of a
  // 64 x 64 frame in every mode (540, 506, 560 pixels on PoCL); 10 % is the floor.
  EXPECT_GT(coveredPixels(*mr, m.render.params()), 410);
  for (Mode mode : {Mode::Dvr, Mode::Mip}) {
    RenderParams p = m.render.params();
    p.mode = mode;
    EXPECT_GT(coveredPixels(*mr, p), 410) << int(mode);
  }
  // Saved while the MR is open, the preferences keep the user's HU threshold.
  EXPECT_NE(preferencesText(m).find("iso=400,"), std::string::npos) << preferencesText(m);
  // A mode chosen on the MR stays; the HU look comes back with the next CT.
  m.render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; });
  openStudy(m, std::make_shared<const Volume>(makeHeadPhantom(32)), "ct again");
  EXPECT_EQ(m.render.params().isoLo, 400.0);
  EXPECT_TRUE(m.render.params().transferFunction.empty());
  EXPECT_EQ(m.render.params().mode, Mode::Dvr);
  EXPECT_FALSE(m.huLook.has_value());
}

TEST(ValueLook, TheStanfordMrBrainShowsItsHead) {
  const std::filesystem::path dir = std::filesystem::path(VOXRAY_DATA_DIR) / "stanford/MRbrain";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no shared data at " << dir;
  RawLayout l;  // a folder of 109 slices, 16-bit unsigned big-endian
  l.dims = {256, 256, 0};
  l.type = SampleType::U16;
  l.order = ByteOrder::Big;
  l.spacingMm = {1.0, 1.0, 1.5};
  const auto v = std::make_shared<const Volume>(importRaw(dir.string(), l));
  // Background about 1028, tissue up to 5119 (shared/data/README.md).
  const ValueLook look = valueLook(*v);
  EXPECT_GE(look.low, 1020.0);
  EXPECT_LE(look.low, 1100.0);
  EXPECT_GT(look.threshold, 1100.0);
  EXPECT_LT(look.threshold, look.high);
  // At the HU look's iso 400 every voxel (>= 1026) was inside: the view showed the box.
  // Now the surface is the head's: 437 of 4096 pixels on PoCL.
  AppModels m;
  openStudy(m, v, "MRbrain");
  EXPECT_EQ(m.render.params().isoLo, look.threshold);
  EXPECT_GT(coveredPixels(*v, m.render.params()), 300);
}
