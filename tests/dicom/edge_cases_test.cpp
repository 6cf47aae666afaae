// edge-cases/failing/*: each one is refused with a message that says why, never loaded
// as a silently wrong volume.
#include "test_data.h"

namespace voxray {
namespace {

using test::dicomPath;

TEST(DicomEdgeCases, RepeatedPositionsAreNotStacked) {
  std::string m = test::importError(dicomPath("edge-cases/failing/notavolume/001"));
  EXPECT_NE(m.find("no series here is a 3D volume"), std::string::npos) << m;
  EXPECT_NE(m.find("4:4: 1 image(s)"), std::string::npos) << m;
  DicomListing l = listDicomSeries(dicomPath("edge-cases/failing/notavolume/001"));
  ASSERT_EQ(l.series.size(), 4u);
  EXPECT_TRUE(test::anyContains(l.series[0].warnings, "4 images at each slice position"));
}

TEST(DicomEdgeCases, TwoSlicesAreTooFew) {
  std::string m = test::importError(dicomPath("edge-cases/failing/slicecount/001"));
  EXPECT_NE(m.find("only 2 images"), std::string::npos) << m;
}

TEST(DicomEdgeCases, EmptyFilesSkippedAndCounted) {
  DicomListing l = listDicomSeries(dicomPath("edge-cases/failing/sliceorientation/001"));
  EXPECT_EQ(l.filesScanned, 4);
  EXPECT_EQ(l.filesSkipped, 2);
  ASSERT_EQ(l.series.size(), 1u);
  EXPECT_FALSE(l.series[0].isVolume);
}

TEST(DicomEdgeCases, ColourImagesRefusedEvenWhenSelected) {
  std::string m = test::importError(dicomPath("edge-cases/generic/rgb/001"));
  EXPECT_NE(m.find("colour image (RGB)"), std::string::npos) << m;
  m = test::importError(dicomPath("edge-cases/generic/rgb/001"), "747197466");
  EXPECT_NE(m.find("colour image (RGB)"), std::string::npos) << m;
}

TEST(DicomEdgeCases, FourDMultiFrameWithoutPositionsNotMixedAcrossFiles) {
  // Six copies of one enhanced MR (different codecs) share a series UID but carry no
  // positions: each file must stay its own candidate, never a 60-slice stack.
  DicomListing l = listDicomSeries(dicomPath("pydicom-data"));
  for (auto& s : l.series) EXPECT_LE(s.sliceCount, 10) << s.selector;
  for (auto& s : l.series) EXPECT_FALSE(s.chosenByDefault);
}

}  // namespace
}  // namespace voxray
