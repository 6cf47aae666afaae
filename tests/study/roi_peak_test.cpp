// SUVpeak (issue 36): the best 1 cm³ sphere of a ROI (voxray/engine/roi_peak.h) and of a 3D
// segment (mask_peak.h, segment_peak.h) against analytic values, and the ROI readout
// (measurementText) that shows it for a PET only.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "measurement_model.h"
#include "segment_peak.h"
#include "voxray/engine/mask_peak.h"
#include "voxray/engine/roi_peak.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom_series.h"
#include "voxray/io/volume.h"

using namespace voxray;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A volume of DIMS voxels of SPACING mm, its axes rotated (30 degrees about z, 20 about x:
// the kernel must not depend on the orientation), values VALUE(i, j, k) stored as int16.
template <class F>
Volume makeVolume(glm::ivec3 dims, glm::dvec3 spacing, F value) {
  Volume v;
  v.dims = dims;
  v.spacingMm = spacing;
  v.originMm = {-12.0, 40.5, 7.25};
  const double a = glm::radians(30.0), b = glm::radians(20.0);
  const glm::dmat3 rz(glm::dvec3(std::cos(a), std::sin(a), 0),
                      glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
  const glm::dmat3 rx(glm::dvec3(1, 0, 0), glm::dvec3(0, std::cos(b), std::sin(b)),
                      glm::dvec3(0, -std::sin(b), std::cos(b)));
  v.direction = rx * rz;
  v.voxels.resize(v.voxelCount());
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) v.voxels[v.index(i, j, k)] = int16_t(value(i, j, k));
  return v;
}

PlaneRoi rect(glm::dvec3 a, glm::dvec3 b, RoiShape shape = RoiShape::Rect) {
  PlaneRoi roi;
  roi.shape = shape;
  roi.normalAxis = 2;
  roi.a = a;
  roi.b = b;
  return roi;
}

Measurement measurement(const PlaneRoi& roi) {
  Measurement m;
  m.kind = roi.shape == RoiShape::Rect ? MeasureKind::Rect : MeasureKind::Ellipse;
  m.normalAxis = roi.normalAxis;
  m.points = {roi.a, roi.b};
  return m;
}

TEST(RoiPeak, TheRadiusIsThatOfOneCubicCentimetre) {
  EXPECT_NEAR(4.0 / 3.0 * kPi * std::pow(kPeakSphereRadiusMm, 3), 1000.0, 1e-9);
}

// A hot sphere of radius 12 mm (7.2 cm³) at 800 in a background of 100: the 1 cm³ sphere fits
// inside it at its centre (6.20 mm plus a cell's half diagonal, 0.87 mm, is under 12), so the
// peak is its uniform value, in physical units after slope and intercept. Exact: every weight
// multiplies the same value (tolerance: rounding of a weighted mean, 1e-12 relative).
TEST(RoiPeak, AHotSphereLargerThanOneCubicCentimetreReadsItsUniformValue) {
  const glm::dvec3 c(24.0, 23.0, 20.0);
  Volume v = makeVolume({48, 46, 40}, {1.0, 1.0, 1.0}, [&](int i, int j, int k) {
    return glm::length(glm::dvec3(i, j, k) - c) <= 12.0 ? 800 : 100;
  });
  v.slope = 2.5;
  v.intercept = -10.0;
  const RoiPeak p =
      roiPeak(v, rect(c - glm::dvec3(15, 15, 0), c + glm::dvec3(15, 15, 0), RoiShape::Ellipse));
  ASSERT_TRUE(p.mean);
  EXPECT_NEAR(*p.mean, 800 * 2.5 - 10.0, 1e-12 * 2000);
  EXPECT_EQ(p.centre.z, 20);
  // A sphere reading 800 lies in the hot voxels' cells, which reach 12 + 0.866 mm from c at
  // most: its centre is within 12.866 - 6.2035 = 6.66 mm of c.
  EXPECT_LE(glm::length(glm::dvec3(p.centre) - c), 6.66);
  EXPECT_GT(p.centres, 0u);
}

// One hot voxel of value H among zeros: the best sphere holds the voxel wholly (weight 1), so the
// peak is H * (voxel volume) / (the weights' volume). That volume is 1000 mm³ up to the 16^3
// sub-sampling of the cells the surface crosses: measured 1000.81 (2 mm cubes), 999.86 (0.7 x 1.3
// x 2.9 mm) and 1000.38 mm³ (4 mm cubes), so the tolerance of 2e-3 relative (2 mm³) leaves a
// factor 2.5 over the worst.
TEST(RoiPeak, ASingleHotVoxelIsSpreadOverTheSphere) {
  struct Grid {
    glm::dvec3 spacing;
    glm::ivec3 dims, hot;
  };
  for (const Grid& g : {Grid{{2.0, 2.0, 2.0}, {24, 24, 24}, {12, 11, 12}},
                        Grid{{0.7, 1.3, 2.9}, {50, 30, 14}, {25, 15, 7}},
                        Grid{{4.0, 4.0, 4.0}, {16, 16, 16}, {8, 8, 8}}}) {
    const double h = 1000.0;
    const Volume v = makeVolume(g.dims, g.spacing, [&](int i, int j, int k) {
      return glm::ivec3(i, j, k) == g.hot ? int(h) : 0;
    });
    const glm::dvec3 hot(g.hot);
    const RoiPeak p = roiPeak(v, rect(hot - glm::dvec3(20, 20, 0), hot + glm::dvec3(20, 20, 0)));
    ASSERT_TRUE(p.mean) << g.spacing.x;
    const double voxelMm3 = g.spacing.x * g.spacing.y * g.spacing.z;
    EXPECT_NEAR(p.sphereMm3, 1000.0, 2.0) << g.spacing.x;
    EXPECT_NEAR(*p.mean, h * voxelMm3 / p.sphereMm3, 1e-12 * h);
    EXPECT_NEAR(*p.mean, h * voxelMm3 / 1000.0, 2e-3 * h * voxelMm3 / 1000.0) << g.spacing.x;
    // Neighbours whose sphere also holds the whole hot voxel tie with it; the first wins.
    EXPECT_LE(glm::length((glm::dvec3(p.centre) - hot) * g.spacing), kPeakSphereRadiusMm);
  }
}

// A linear field: the sphere's weights are symmetric about its centre, so the weighted mean is
// the field at the centre, and the peak is at the ROI voxel with room for the sphere that has
// the highest value. 2 mm voxels: the footprint reaches 3 voxels (6.2035 mm) each way in the
// plane, so the rectangle of voxels 5..20 has room at 8..17.
TEST(RoiPeak, ALinearFieldPeaksAtTheLastCentreWithRoom) {
  const Volume v = makeVolume({30, 30, 20}, {2.0, 2.0, 2.0},
                              [](int i, int j, int k) { return 10 * i + 3 * j + k; });
  const RoiPeak p = roiPeak(v, rect({5, 5, 10}, {20, 20, 10}));
  ASSERT_TRUE(p.mean);
  EXPECT_EQ(p.centre, glm::ivec3(17, 17, 10));
  EXPECT_NEAR(*p.mean, 10 * 17 + 3 * 17 + 10, 1e-9);
  EXPECT_EQ(p.centres, 100u);  // 10 x 10
}

// No room: a 10 x 10 mm square (6 x 6 voxels of 2 mm) is narrower than the sphere (12.4 mm);
// a large ROI on the second slice has the sphere reaching out of the volume. No number.
TEST(RoiPeak, NoRoomForTheSphereGivesNoPeak) {
  Volume v = makeVolume({30, 30, 20}, {2.0, 2.0, 2.0}, [](int, int, int) { return 500; });
  const RoiPeak narrow = roiPeak(v, rect({10, 10, 10}, {15, 15, 10}));
  EXPECT_FALSE(narrow.mean);
  EXPECT_EQ(narrow.centres, 0u);
  // One voxel wider (7 x 7 voxels, 14 mm) has exactly one centre.
  const RoiPeak wide = roiPeak(v, rect({10, 10, 10}, {16, 16, 10}));
  ASSERT_TRUE(wide.mean);
  EXPECT_EQ(wide.centres, 1u);
  EXPECT_EQ(wide.centre, glm::ivec3(13, 13, 10));
  EXPECT_FALSE(roiPeak(v, rect({2, 2, 1}, {27, 27, 1})).mean);
  EXPECT_TRUE(roiPeak(v, rect({2, 2, 4}, {27, 27, 4})).mean);  // the sphere reaches k 1..7

  v.suv = SuvScale{0.002, "SUVbw"};
  const std::string text = measurementText(v, measurement(rect({10, 10, 10}, {15, 15, 10})));
  EXPECT_NE(text.find("SUVmax 1.000  SUVpeak — (no room for 1 cm³) SUVbw"), std::string::npos)
      << text;
}

TEST(RoiPeak, ABadRadiusIsRefused) {
  const Volume v = makeVolume({8, 8, 8}, {2.0, 2.0, 2.0}, [](int, int, int) { return 1; });
  EXPECT_THROW(roiPeak(v, rect({1, 1, 4}, {6, 6, 4}), 0.0), Error);
  EXPECT_THROW(roiPeak(v, rect({1, 1, 4}, {6, 6, 4}), NAN), Error);
}

// The readout: a PET shows SUVpeak beside SUVmax in its SUV unit; any other volume none.
TEST(RoiPeakReadout, PetShowsSuvPeakOthersDoNot) {
  const glm::dvec3 c(16.0, 16.0, 12.0);
  Volume v = makeVolume({32, 32, 24}, {2.0, 2.0, 2.0}, [&](int i, int j, int k) {
    return glm::length(glm::dvec3(i, j, k) - c) <= 8.0 ? 4000 : 1000;  // radius 16 mm
  });
  const Measurement m =
      measurement(rect(c - glm::dvec3(10, 10, 0), c + glm::dvec3(10, 10, 0), RoiShape::Ellipse));
  const std::string ct = measurementText(v, m);
  EXPECT_EQ(ct.find("peak"), std::string::npos) << ct;
  v.unit = "Bq/mL";
  v.suv = SuvScale{0.001, "SUVbw"};
  const std::string pet = measurementText(v, m);
  EXPECT_NE(pet.find("SUVmax 4.000  SUVpeak 4.000 SUVbw"), std::string::npos) << pet;
}

}  // namespace

// Issue 36, SUVpeak of 3D segments (voxray/engine/mask_peak.h, segment_peak.h).

namespace {

// The box LO..HI (voxels, both ends included) of V's grid as label 1.
std::vector<uint8_t> boxLabels(const Volume& v, glm::ivec3 lo, glm::ivec3 hi) {
  std::vector<uint8_t> labels(v.voxelCount(), 0);
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) labels[v.index(i, j, k)] = 1;
  return labels;
}

}  // namespace

TEST(MaskPeak, OnARampTheBestSphereIsTheHighestCentreWhoseSphereFitsTheSegment) {
  // 2 mm voxels, value 10 i: the 1 cm³ sphere (radius 6.2 mm) holds the voxel centres up to
  // 3 voxels away, so the best centre is 3 voxels inside the box's high i face (i = 27), and
  // a kernel symmetric about its centre averages a linear ramp to the centre's value.
  const Volume v = makeVolume({40, 40, 40}, {2, 2, 2}, [](int i, int, int) { return 10 * i; });
  const auto labels = boxLabels(v, {8, 8, 8}, {30, 30, 30});
  const RoiPeak p = maskPeak(v, labels, 1);
  ASSERT_TRUE(p.mean);
  EXPECT_NEAR(*p.mean, 270.0, 1e-9);
  EXPECT_EQ(p.centre, glm::ivec3(27, 11, 11));  // ties: the first in voxel order
  EXPECT_EQ(p.centres, size_t(17 * 17 * 17));   // 11 ... 27 on each axis
  // The weights sum to the sphere's 1000 mm³ (the kernel's sub-sampling: ~1e-3 relative).
  EXPECT_NEAR(p.sphereMm3, 1000.0, 2.0);
  // Another label is not the segment.
  EXPECT_FALSE(maskPeak(v, labels, 2).mean);
  // 10 mm across: no centre has room.
  const RoiPeak small = maskPeak(v, boxLabels(v, {10, 10, 10}, {14, 14, 14}), 1);
  EXPECT_FALSE(small.mean);
  EXPECT_EQ(small.centres, size_t(0));
  EXPECT_THROW(maskPeak(v, std::vector<uint8_t>(10, 1), 1), Error);
}

TEST(MaskPeak, ASegmentOnAnotherGridIsTakenByTheNearestVoxel) {
  // FROM: 1 mm voxels at the origin; ONTO: 2 mm voxels shifted by 0.4 mm in x, so onto's voxel
  // i lies at from's i' = 2 i + 0.4, nearest 2 i: in the box 5 ... 14 for i = 3 ... 7.
  VoxelGrid from;
  from.dims = {20, 20, 20};
  Volume onto;
  onto.dims = {10, 10, 10};
  onto.spacingMm = {2, 2, 2};
  onto.originMm = {0.4, 0, 0};
  onto.voxels.assign(onto.voxelCount(), 0);
  std::vector<uint8_t> labels(from.voxelCount(), 0);
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 5; i <= 14; ++i) labels[from.index(i, j, k)] = 3;
  const auto on = maskOnGrid(from, labels, 3, onto);
  for (int i = 0; i < 10; ++i)
    EXPECT_EQ(int(on[onto.index(i, 4, 4)]), i >= 3 && i <= 7 ? 1 : 0) << "i " << i;
}

TEST(SegmentPeak, ThePetSpheresSuvPeakOnThePetAndThroughAFusedOverlay) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("voxray-segment-peak-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  const PetSpherePhantom phantom;
  writePetSpherePhantom((dir / "pet").string(), phantom);
  auto pet = std::make_shared<const Volume>(loadVolume((dir / "pet").string()));
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(pet->suv);
  const double suv = petSphereSuv(phantom);
  // The sphere (uniform activity) segmented on the PET: the peak is the sphere's SUV.
  Segmentation s = emptySegmentation(*pet);
  for (size_t n = 0; n < s.labels.size(); ++n)
    s.labels[n] = pet->toPhysical(pet->voxels[n]) > 10000.0 ? 1 : 0;
  s.segments = {Segment{}};
  auto stats = allSegmentStats(s, *pet);
  addSuvPeaks(stats, s, *pet);
  ASSERT_TRUE(stats[0].suvPeak);
  // 1e-9 relative: every voxel of the sphere holds the same stored value.
  EXPECT_NEAR(*stats[0].suvPeak, suv, 1e-9 * suv);
  EXPECT_EQ(stats[0].peakOf, "");
  // A CT-like volume of its own grid (1.5 mm voxels, shifted) with no SUV, the PET fused over
  // it: a ball of 30 mm about the sphere's centre, drawn on the CT, is taken onto the PET grid.
  Volume ct;
  ct.dims = {120, 120, 80};
  ct.spacingMm = {1.5, 1.5, 1.5};
  const glm::dvec3 centre =
      pet->originMm + pet->direction * (pet->spacingMm * 0.5 * glm::dvec3(pet->dims - 1));
  ct.originMm = centre - 0.5 * ct.spacingMm * glm::dvec3(ct.dims - 1) + glm::dvec3(0.3, -0.7, 0.2);
  ct.voxels.assign(ct.voxelCount(), 0);
  Segmentation onCt = emptySegmentation(ct);
  for (int k = 0; k < ct.dims.z; ++k)
    for (int j = 0; j < ct.dims.y; ++j)
      for (int i = 0; i < ct.dims.x; ++i)
        if (glm::length(onCt.grid.toPatient({i, j, k}) - centre) <= 30.0)
          onCt.labels[ct.index(i, j, k)] = 1;
  onCt.segments = {Segment{}};
  auto fused = allSegmentStats(onCt, ct);
  addSuvPeaks(fused, onCt, ct, pet.get(), "PET sphere");
  ASSERT_TRUE(fused[0].suvPeak);
  EXPECT_NEAR(*fused[0].suvPeak, suv, 1e-9 * suv);
  EXPECT_EQ(fused[0].peakOf, "PET sphere");
  EXPECT_EQ(fused[0].unit, "HU");  // the CT's own statistics stay its own
  // Without an SUV anywhere: none, no note.
  auto plain = allSegmentStats(onCt, ct);
  addSuvPeaks(plain, onCt, ct);
  EXPECT_FALSE(plain[0].suvPeak);
  EXPECT_TRUE(plain[0].peakNote.empty());
  // A segment of 8 mm across on the PET: no room, said.
  Segmentation tiny = emptySegmentation(*pet);
  tiny.labels[pet->index(24, 24, 16)] = 1;
  tiny.labels[pet->index(25, 24, 16)] = 1;
  tiny.segments = {Segment{}};
  auto none = allSegmentStats(tiny, *pet);
  addSuvPeaks(none, tiny, *pet);
  EXPECT_FALSE(none[0].suvPeak);
  EXPECT_EQ(none[0].peakNote, kNoRoomForPeakInSegment);
}
