// The window a series asks to be shown with (WindowCenter/WindowWidth), and its modality:
// the workstation opens a series with them (study_state.h).
#include "test_data.h"

namespace voxray {
namespace {

using test::dicomPath;

void expectWindow(const std::string& rel, double width, double level,
                  const std::string& explanation) {
  SCOPED_TRACE(rel);
  Volume v = importDicom(dicomPath(rel));
  ASSERT_TRUE(v.window.has_value());
  EXPECT_DOUBLE_EQ(v.window->width, width);
  EXPECT_DOUBLE_EQ(v.window->level, level);
  EXPECT_EQ(v.window->explanation, explanation);
}

TEST(DicomDisplayWindow, FromTheHeaderInPhysicalUnits) {
  expectWindow("ct-ge-tilt", 100.0, 35.0, "");
  expectWindow("transfer-syntaxes/1.dcm", 1639.0, 763.0, "Algo1");  // an MR slice
  // Enhanced CT: the FrameVOILUT functional group.
  expectWindow("pydicom-data/eCT_Supplemental.dcm", 102.0, 49.0, "");
}

TEST(DicomDisplayWindow, SeveralPairsGiveTheFirst) {
  // Centres 40\450, widths 350\1500, explanations WINDOW1\WINDOW2.
  expectWindow("pydicom-data/bad_sequence.dcm", 350.0, 40.0, "WINDOW1");
  // The volume S2010's window (40/80, twice), not the scout S1000's (-671/2062).
  expectWindow("ct-philips-phantom", 80.0, 40.0, "");
}

TEST(DicomDisplayWindow, ModalityAndNoWindowWhenTheHeaderHasNone) {
  EXPECT_EQ(importDicom(dicomPath("ct-ge-tilt")).modality, "CT");
  EXPECT_EQ(importDicom(dicomPath("transfer-syntaxes/1.dcm")).modality, "MR");
  Volume ct = importDicom(dicomPath("ct-visible-human-pelvis"));
  EXPECT_EQ(ct.modality, "CT");
  EXPECT_FALSE(ct.window.has_value());
  Volume mr = importDicom(dicomPath("edge-cases/generic/anatomical/001"));
  EXPECT_EQ(mr.modality, "MR");
  EXPECT_FALSE(mr.window.has_value());
}

}  // namespace
}  // namespace voxray
