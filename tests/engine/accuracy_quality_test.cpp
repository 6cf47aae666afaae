// The quality presets in resources/quality/ hold what they claim: balanced renders CThead
// dvr at >= 40 dB PSNR against the reference renderer at 1/16-voxel steps, with at most a
// quarter of the reference preset's volume reads (the speed-up the sweep measured in
// time; reads are counted exactly, so the test does not depend on a busy machine's clock).
#include <gtest/gtest.h>

#include <map>

#include "accuracy_cthead.h"
#include "stability_helpers.h"
#include "voxray/engine/quality.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"
#include "voxray/lab/accuracy.h"

namespace voxray {

namespace {

std::map<std::string, QualityPreset> presets() {
  std::map<std::string, QualityPreset> m;
  for (const QualityPreset& q : builtinQualityPresets()) m[q.name] = q;
  return m;
}

}  // namespace

TEST(AccuracyQuality, PresetsParseAndAreOrderedBySpeed) {
  // Embedded in the binary, fastest first: the order the UI's quality control lists.
  const auto& list = builtinQualityPresets();
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].name, "interactive");
  EXPECT_EQ(list[1].name, "balanced");
  EXPECT_EQ(list[2].name, "reference");
  EXPECT_EQ(&findQualityPreset("Balanced"), &list[1]);
  EXPECT_THROW(findQualityPreset("ultra"), Error);
  auto m = presets();
  ASSERT_EQ(m.count("interactive"), 1u);
  ASSERT_EQ(m.count("balanced"), 1u);
  ASSERT_EQ(m.count("reference"), 1u);
  EXPECT_GT(m["balanced"].stepVoxels, m["reference"].stepVoxels);
  EXPECT_GE(m["interactive"].stepVoxels, m["balanced"].stepVoxels);
  EXPECT_GE(m["balanced"].measuredPsnrDb, 40.0);
  EXPECT_GE(m["balanced"].measuredSpeedup, 4.0);
  EXPECT_THROW(parseQualityPreset("{\"name\": \"x\", \"step_voxels\": 0}", "test"), Error);
  EXPECT_THROW(parseQualityPreset("not json", "test"), Error);
}

TEST(AccuracyQuality, BalancedMeetsFortyDecibelsAtAQuarterOfTheReads) {
  if (!test::cthead()) GTEST_SKIP() << "CThead not found in " VOXRAY_SHARED_DATA;
  const Volume& v = *test::cthead();
  auto m = presets();
  RenderParams base = test::ctheadDvr();
  // The reference: the reference preset's operator, at 1/16 voxel steps.
  RenderParams fine = applyQuality(base, m["reference"], v);
  fine.stepMm = 1.0 / 16;
  FloatImage truth = renderReferenceFloat(v, fine);

  RenderParams balanced = applyQuality(base, m["balanced"], v);
  RenderParams reference = applyQuality(base, m["reference"], v);
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  ImageError e = compareImages(toFloatImage(rc.render(balanced)), truth);
  RecordProperty("balanced_psnr_db", std::to_string(e.psnrDb));
  EXPECT_GE(e.psnrDb, 40.0);

  ReferenceHits b, r;
  renderReferenceFloat(v, balanced, &b);
  renderReferenceFloat(v, reference, &r);
  RecordProperty("reads_ratio", std::to_string(r.samples / b.samples));
  EXPECT_GE(r.samples / b.samples, 4.0);
}

}  // namespace voxray
