// The window a series asks to be shown with (WindowCenter/WindowWidth), and its modality:
// the workstation opens a series with them (study_state.h).
#include "test_data.h"

namespace voxray {
namespace {

using test::dicomPath;

TEST(DicomDisplayWindow, FirstPairOfTheHeaderInPhysicalUnits) {
  Volume v = importDicom(dicomPath("ct-ge-tilt"));  // WindowCenter 35, WindowWidth 100
  EXPECT_EQ(v.modality, "CT");
  ASSERT_TRUE(v.window.has_value());
  EXPECT_DOUBLE_EQ(v.window->width, 100.0);
  EXPECT_DOUBLE_EQ(v.window->level, 35.0);
  EXPECT_EQ(v.window->explanation, "");
}

TEST(DicomDisplayWindow, SeveralPairsGiveTheFirst) {
  // Centres 40\450, widths 350\1500, explanations WINDOW1\WINDOW2.
  Volume v = importDicom(dicomPath("pydicom-data/bad_sequence.dcm"));
  ASSERT_TRUE(v.window.has_value());
  EXPECT_DOUBLE_EQ(v.window->width, 350.0);
  EXPECT_DOUBLE_EQ(v.window->level, 40.0);
  EXPECT_EQ(v.window->explanation, "WINDOW1");
  // The scout S1000 has another window (-671/2062) than the volume S2010 (40/80, twice).
  Volume phantom = importDicom(dicomPath("ct-philips-phantom"));
  ASSERT_TRUE(phantom.window.has_value());
  EXPECT_DOUBLE_EQ(phantom.window->width, 80.0);
  EXPECT_DOUBLE_EQ(phantom.window->level, 40.0);
}

TEST(DicomDisplayWindow, ExplanationKept) {
  Volume v = importDicom(dicomPath("transfer-syntaxes/1.dcm"));  // MR, 763/1639 "Algo1"
  EXPECT_EQ(v.modality, "MR");
  ASSERT_TRUE(v.window.has_value());
  EXPECT_DOUBLE_EQ(v.window->width, 1639.0);
  EXPECT_DOUBLE_EQ(v.window->level, 763.0);
  EXPECT_EQ(v.window->explanation, "Algo1");
}

TEST(DicomDisplayWindow, EnhancedFromTheFrameVoiLutGroup) {
  Volume v = importDicom(dicomPath("pydicom-data/eCT_Supplemental.dcm"));  // shared group
  ASSERT_TRUE(v.window.has_value());
  EXPECT_DOUBLE_EQ(v.window->width, 102.0);
  EXPECT_DOUBLE_EQ(v.window->level, 49.0);
}

TEST(DicomDisplayWindow, NoneWhenTheHeaderHasNone) {
  Volume ct = importDicom(dicomPath("ct-visible-human-pelvis"));
  EXPECT_EQ(ct.modality, "CT");
  EXPECT_FALSE(ct.window.has_value());
  Volume mr = importDicom(dicomPath("edge-cases/generic/anatomical/001"));
  EXPECT_EQ(mr.modality, "MR");
  EXPECT_FALSE(mr.window.has_value());
}

}  // namespace
}  // namespace voxray
