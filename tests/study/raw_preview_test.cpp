// The raw dialog's model: the preview's value range with its HU hint, and the patient
// letters of the preview (the size check is io's: tests/io/raw_check_test.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "../io/test_support.h"
#include "raw_preview.h"
#include "voxray/io/orientation.h"

using namespace voxray;

namespace {

const std::string kCtHead = voxray::test::dataPath("stanford/CThead");

}  // namespace

TEST(RawPreview, ValueRangeIsRescaledAndHintsWhenItIsNotHu) {
  RawLayout l = voxray::test::ctHeadFolderLayout();
  auto p = previewRawSlice(kCtHead, l);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->image.width, 256);
  EXPECT_GE(p->lo, 0.0);  // CThead stores 0 for air: not HU
  EXPECT_GT(p->hi, 1000.0);
  std::string raw = valueRangeText(*p, l);
  EXPECT_NE(raw.find("not HU?"), std::string::npos) << raw;
  l.intercept = -1024.0;
  std::string hu = valueRangeText(*p, l);
  EXPECT_EQ(hu.find("not HU?"), std::string::npos) << hu;
  char expected[64];
  std::snprintf(expected, sizeof expected, "middle slice: %g … %g", p->lo - 1024.0, p->hi - 1024.0);
  EXPECT_EQ(hu, expected);
}

TEST(RawPreview, EdgeLettersFollowTheAxesCode) {
  EdgeLetters lpi = edgeLetters(directionFromAxesCode("LPI"));
  EXPECT_EQ(std::string({lpi.left, lpi.right, lpi.top, lpi.bottom, lpi.slices}), "RLAPI");
  EdgeLetters ras = edgeLetters(directionFromAxesCode("RAS"));
  EXPECT_EQ(std::string({ras.left, ras.right, ras.top, ras.bottom, ras.slices}), "LRPAS");
  EdgeLetters pil = edgeLetters(directionFromAxesCode("PIL"));
  EXPECT_EQ(std::string({pil.left, pil.right, pil.top, pil.bottom, pil.slices}), "APSIL");
}
