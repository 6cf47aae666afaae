// The measurement maths (voxray/engine/measure.h) and model (measurement_model.h): values
// against analytic ones, the shared tilted GE series against its DICOM positions, the ROI
// pixel rule, and the bad inputs that must read "—" rather than NaN.
#include <cmath>
#include <cstdio>
#include <numeric>

#include <gtest/gtest.h>

#include "measurement_json.h"
#include "measurement_model.h"
#include "slice_image.h"
#include "status_text.h"
#include "surface_pick.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/synthetic.h"

using namespace voxray;

namespace {

// An anisotropic, oblique volume: 0.7 x 1.3 x 2.9 mm voxels whose axes are rotated 30 degrees
// about z and 20 about x, values VALUE(i, j, k).
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

Volume anisotropic() {
  return makeVolume({20, 16, 8}, {0.7, 1.3, 2.9}, [](int i, int j, int) { return i + 10 * j; });
}

// Patient positions read from the DICOM file itself with dcmdump: the pixel (COL, ROW) of
// FILE is at ImagePositionPatient + col * spacing * rowDir + row * spacing * colDir.
glm::dvec3 dicomPixelMm(const std::string& file, double col, double row) {
  const std::string cmd = "dcmdump +P 0020,0032 +P 0020,0037 +P 0028,0030 '" + file + "'";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return glm::dvec3(NAN);
  double ipp[3] = {NAN, NAN, NAN}, iop[6] = {NAN}, ps[2] = {NAN, NAN};
  char line[512];
  while (std::fgets(line, sizeof line, pipe)) {
    std::string s(line);
    const auto open = s.find('['), close = s.find(']');
    if (open == std::string::npos || close == std::string::npos) continue;
    std::string values = s.substr(open + 1, close - open - 1);
    for (char& c : values)
      if (c == '\\') c = ' ';
    if (s.find("ImagePositionPatient") != std::string::npos)
      std::sscanf(values.c_str(), "%lf %lf %lf", &ipp[0], &ipp[1], &ipp[2]);
    if (s.find("ImageOrientationPatient") != std::string::npos)
      std::sscanf(values.c_str(), "%lf %lf %lf %lf %lf %lf", &iop[0], &iop[1], &iop[2], &iop[3],
                  &iop[4], &iop[5]);
    if (s.find("PixelSpacing") != std::string::npos)
      std::sscanf(values.c_str(), "%lf %lf", &ps[0], &ps[1]);
  }
  pclose(pipe);
  // PixelSpacing is (row spacing, column spacing): along a column first.
  return glm::dvec3(ipp[0], ipp[1], ipp[2]) + col * ps[1] * glm::dvec3(iop[0], iop[1], iop[2]) +
         row * ps[0] * glm::dvec3(iop[3], iop[4], iop[5]);
}

}  // namespace

TEST(Measure, DistanceBetweenVoxelCentresOfAnisotropicObliqueVolumeIsAnalytic) {
  const Volume v = anisotropic();
  const glm::dvec3 a(1, 2, 3), b(7, 9, 5);
  const double analytic = std::sqrt(6 * 0.7 * 6 * 0.7 + 7 * 1.3 * 7 * 1.3 + 2 * 2.9 * 2 * 2.9);
  EXPECT_NEAR(distanceMm(v, a, b), analytic, 1e-6);
  EXPECT_NEAR(distanceMm(v, a, a + glm::dvec3(0, 0, 1)), 2.9, 1e-6);  // one slice gap
  // The patient position inverts back to the voxel.
  const glm::dvec3 back = patientToVoxel(v, voxelToPatient(v, b));
  EXPECT_NEAR(glm::length(back - b), 0.0, 1e-9);
}

TEST(Measure, AngleIsMeasuredInPatientSpaceNotInVoxels) {
  const Volume v = anisotropic();
  // Arms along i and j: perpendicular in patient space (orthonormal direction).
  EXPECT_NEAR(*angleDeg(v, {5, 0, 0}, {0, 0, 0}, {0, 5, 0}), 90.0, 1e-9);
  // The voxel diagonal (1, 1) against i: atan(1.3 / 0.7) in mm, not 45 degrees.
  EXPECT_NEAR(*angleDeg(v, {1, 0, 0}, {0, 0, 0}, {1, 1, 0}), glm::degrees(std::atan2(1.3, 0.7)),
              1e-9);
  EXPECT_NEAR(*angleDeg(v, {1, 0, 0}, {0, 0, 0}, {-3, 0, 0}), 180.0, 1e-9);
  EXPECT_FALSE(angleDeg(v, {1, 1, 1}, {1, 1, 1}, {2, 0, 0}));  // zero-length arm: no angle
}

TEST(Measure, TiltedGeSeriesDistanceEqualsDicomPositions) {
  const std::string dir = std::string(VOXRAY_DATA_DIR) + "/dicom/ct-ge-tilt/";
  const Volume v = loadVolume(dir);
  ASSERT_GT(v.voxelCount(), 0U);
  // Pixel (100, 20) of the 3rd file and (400, 300) of the 20th: apart along the rows, along
  // the tilted columns (18.5 degrees out of the axial plane) and across 17 uneven gaps.
  const glm::dvec3 pa = dicomPixelMm(dir + "03.dcm", 100, 20);
  const glm::dvec3 pb = dicomPixelMm(dir + "20.dcm", 400, 300);
  ASSERT_TRUE(std::isfinite(pa.x) && std::isfinite(pb.x)) << "dcmdump could not read the files";
  const glm::dvec3 a = patientToVoxel(v, pa), b = patientToVoxel(v, pb);
  EXPECT_TRUE(insideVolume(v, a));
  EXPECT_TRUE(insideVolume(v, b));
  EXPECT_NEAR(distanceMm(v, a, b), glm::length(pb - pa), 1e-6);
  // On the resampled grid the points lie on other voxel rows and slices than in the files.
  EXPECT_GT(std::abs((b - a).z), 1.0);
  // The last row of the first slice falls 79 mm below its table position: still inside.
  EXPECT_TRUE(insideVolume(v, patientToVoxel(v, dicomPixelMm(dir + "01.dcm", 256, 511))));
}

TEST(Measure, RectRoiStatisticsOnKnownValues) {
  const Volume v = anisotropic();  // value = i + 10 j
  PlaneRoi roi{RoiShape::Rect, 2, {2, 3, 4}, {5, 7, 4}};
  const RoiStats s = roiStats(v, roi);
  // Centres i = 2..5 and j = 3..7 lie inside (the boundary counts): 4 x 5 pixels.
  EXPECT_EQ(s.pixels, 20U);
  EXPECT_NEAR(*s.mean, 3.5 + 10 * 5.0, 1e-9);
  // Sample variance of i + 10 j over the grid: var(i) + 100 var(j) with n - 1 = 19.
  const double varI = (4 * 5) * (1.25) / 19.0, varJ = (4 * 5) * 2.0 / 19.0;
  EXPECT_NEAR(*s.sd, std::sqrt(varI + 100 * varJ), 1e-9);
  EXPECT_DOUBLE_EQ(*s.min, 2 + 30);
  EXPECT_DOUBLE_EQ(*s.max, 5 + 70);
  EXPECT_NEAR(s.areaMm2, (3 * 0.7) * (4 * 1.3), 1e-12);
}

TEST(Measure, EllipseRoiCountsPixelsWhoseCentreIsInside) {
  const Volume v = makeVolume({12, 12, 1}, {1, 1, 1}, [](int, int, int) { return 100; });
  // A circle of radius 2 around voxel (5, 5): centres with dx^2 + dy^2 <= 4, boundary
  // included: 1 + 4 (axes) + 4 (diagonals) + 4 (at distance 2) = 13.
  RoiStats s = roiStats(v, {RoiShape::Ellipse, 2, {3, 3, 0}, {7, 7, 0}});
  EXPECT_EQ(s.pixels, 13U);
  EXPECT_NEAR(s.areaMm2, 3.14159265358979 * 4, 1e-9);
  // Radius 2.5: adds the 8 centres at (2, 1), not those at (2, 2) (8 > 6.25): 21.
  s = roiStats(v, {RoiShape::Ellipse, 2, {2.5, 2.5, 0}, {7.5, 7.5, 0}});
  EXPECT_EQ(s.pixels, 21U);
  EXPECT_DOUBLE_EQ(*s.mean, 100.0);
  EXPECT_DOUBLE_EQ(*s.sd, 0.0);
  // A rectangle whose edges run between centres: only the centres strictly within.
  s = roiStats(v, {RoiShape::Rect, 2, {2.5, 2.5, 0}, {4.5, 5.5, 0}});
  EXPECT_EQ(s.pixels, 2U * 3U);
}

TEST(Measure, RoiInAnotherPlaneUsesThatPlanesSpacing) {
  const Volume v = anisotropic();
  // Across j: a rectangle in the (k, i) plane, 2 slices by 4 columns.
  const RoiStats s = roiStats(v, {RoiShape::Rect, 1, {1, 6, 2}, {5, 6, 4}});
  EXPECT_EQ(s.pixels, 5U * 3U);
  EXPECT_NEAR(s.areaMm2, (2 * 2.9) * (4 * 0.7), 1e-12);
  EXPECT_NEAR(*s.mean, 3 + 60.0, 1e-9);
}

TEST(Measure, PelvisAirAndFemoralHeadCortex) {
  const Volume v = loadVolume(std::string(VOXRAY_DATA_DIR) + "/dicom/ct-visible-human-pelvis");
  ASSERT_EQ(v.dims, glm::ivec3(512, 512, 150));
  // Voxel coordinates (i, j, k) of the loaded volume (1 mm voxels, identity direction, slice
  // k = 1 at z = 901 mm, through both femoral heads).
  // Air in front of the abdomen, inside the scanner's field of view (its corners are padded
  // with -1024): a circle of radius 10 voxels around (250, 100), 317 pixels.
  const RoiStats air = roiStats(v, {RoiShape::Ellipse, 2, {240, 90, 1}, {260, 110, 1}});
  ASSERT_TRUE(air.mean);
  EXPECT_EQ(air.pixels, 317U);
  EXPECT_NEAR(*air.mean, -1000.0, 10.0);
  // The medial rim of the right femoral head (the screen's left head, centre near (150, 243)):
  // a circle of radius 1 around (167, 243), 5 pixels. The subchondral cortex of this
  // cadaver is thin: a 3 x 3 circle there already takes in trabecular bone (about 640 HU).
  const RoiStats bone = roiStats(v, {RoiShape::Ellipse, 2, {166, 242, 1}, {168, 244, 1}});
  ASSERT_TRUE(bone.mean);
  EXPECT_EQ(bone.pixels, 5U);
  EXPECT_GT(*bone.mean, 700.0);
}

TEST(Measure, BadInputReadsDashNeverNan) {
  const Volume v = anisotropic();
  MeasurementModel m;
  auto text = [&](MeasureKind k, std::vector<glm::dvec3> p) {
    int id = m.add(k, std::move(p), 2);
    return measurementText(v, *m.find(id));
  };
  EXPECT_EQ(text(MeasureKind::Distance, {{3, 3, 3}, {3, 3, 3}}), "0.0 mm");  // zero length
  EXPECT_EQ(text(MeasureKind::Angle, {{3, 3, 3}, {3, 3, 3}, {5, 3, 3}}), "—°");
  // Zero area: no pixel, no statistics.
  const std::string flat = text(MeasureKind::Ellipse, {{3, 3, 3}, {3, 9, 3}});
  EXPECT_EQ(flat, "mean —  SD —  min —  max — HU, 0.0 mm², 0 px");
  // Entirely outside the volume: area but no pixel.
  const std::string outside = text(MeasureKind::Rect, {{-30, -30, 3}, {-20, -20, 3}});
  EXPECT_EQ(outside.rfind("mean —", 0), 0U) << outside;
  EXPECT_NE(outside.find(", 0 px"), std::string::npos);
  // Half outside: the pixels inside count; a line leaving the volume still has its length.
  const RoiStats half =
      measurementStats(v, *m.find(m.add(MeasureKind::Rect, {{-5, 0, 1}, {1, 1, 1}}, 2)));
  EXPECT_EQ(half.pixels, 4U);
  EXPECT_EQ(text(MeasureKind::Distance, {{0, 0, 0}, {-10, 0, 0}}), "7.0 mm");
  // A point-sized rectangle has zero area: nothing, even on a voxel centre.
  const std::string one = text(MeasureKind::Rect, {{4, 4, 2}, {4, 4, 2}});
  EXPECT_EQ(one, "mean —  SD —  min —  max — HU, 0.0 mm², 0 px");
  // A corner far outside (a hand-edited session, the CLI): the pixels inside still count.
  EXPECT_EQ(roiStats(v, {RoiShape::Rect, 2, {-1e12, -1e12, 4}, {3, 2, 4}}).pixels, 4U * 3U);
  // A single pixel has a mean but no sample SD.
  const RoiStats single = roiStats(v, {RoiShape::Rect, 2, {3.6, 3.6, 2}, {4.4, 4.4, 2}});
  EXPECT_EQ(single.pixels, 1U);
  EXPECT_TRUE(single.mean);
  EXPECT_FALSE(single.sd);
  // MR: scanner units carried through, values plain numbers.
  Volume mr = anisotropic();
  mr.unit = "scanner units";
  mr.modality = "MR";
  const std::string mrText =
      measurementText(mr, *m.find(m.add(MeasureKind::Rect, {{2, 3, 4}, {5, 7, 4}}, 2)));
  EXPECT_EQ(mrText, "mean 53.5  SD 14.6  min 32  max 75 scanner units, 10.9 mm², 20 px");
  for (const auto& item : m.items())
    EXPECT_EQ(measurementText(v, item).find("nan"), std::string::npos);
}

TEST(Measure, ProbeReadsAsTheViewSamples) {
  const Volume v = anisotropic();  // value = i + 10 j
  const glm::dvec3 at(4.3, 2.6, 1.0);
  const CursorProbe nearest = probeAt(v, at, Interp::Nearest);
  ASSERT_TRUE(nearest.inside);
  EXPECT_EQ(nearest.voxel, glm::ivec3(4, 3, 1));
  EXPECT_DOUBLE_EQ(nearest.value, 4 + 30);
  EXPECT_NEAR(glm::length(nearest.patientMm - voxelToPatient(v, {4, 3, 1})), 0.0, 1e-9);
  const CursorProbe linear = probeAt(v, at, Interp::Linear);
  EXPECT_NEAR(linear.value, 4.3 + 26.0, 1e-4);  // the field is linear: trilinear is exact
  EXPECT_NEAR(glm::length(linear.patientMm - voxelToPatient(v, at)), 0.0, 1e-9);
  const CursorProbe outside = probeAt(v, {-3, 2, 1}, Interp::Linear);
  EXPECT_FALSE(outside.inside);
  const std::string text = formatCursorProbe(outside);
  EXPECT_EQ(text.rfind("— (outside the volume)\n", 0), 0U) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

TEST(Measure, PatientPositionUsesTheLettersOfTheUsersConvention) {
  EXPECT_EQ(formatPatientMm({-12.34, 45.66, -7.0}), "R 12.3  P 45.7  I 7.0 mm");
  EXPECT_EQ(formatPatientMm({3.0, -0.04, 80.0}), "L 3.0  P 0.0  S 80.0 mm");
  EXPECT_EQ(formatPatientMm({0.0, -2.5, 0.0}), "L 0.0  A 2.5  S 0.0 mm");
  CursorProbe p;
  p.inside = true;
  p.value = -998.4;
  p.unit = "HU";
  p.voxel = {128, 200, 75};
  p.patientMm = {-10, -20, 30};
  EXPECT_EQ(formatCursorProbe(p), "-998 HU  [128, 200, 75]\nR 10.0  A 20.0  S 30.0 mm");
}

TEST(Measure, JsonRoundTripAndBadEntries) {
  MeasurementModel m;
  m.add(MeasureKind::Distance, {{1, 2, 3}, {4.5, 6, 7}}, 2);
  m.add(MeasureKind::Angle, {{1, 0, 0}, {0, 0, 0}, {0, 1, 0}}, 0);
  m.add(MeasureKind::Ellipse, {{1, 1, 2}, {5, 6, 2}}, 1);
  m.add(MeasureKind::Distance, {{1, 1, 1}, {9, 9, 9}}, -1);  // picked in 3D
  m.setShowInExports(true);
  const nlohmann::json j = measurementsToJson(m);
  MeasurementModel back;
  measurementsFromJson(nlohmann::json::parse(j.dump()), back);
  ASSERT_EQ(back.items().size(), 4U);
  EXPECT_TRUE(back.showInExports());
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(back.items()[i].kind, m.items()[i].kind);
    EXPECT_EQ(back.items()[i].normalAxis, m.items()[i].normalAxis);
    EXPECT_EQ(back.items()[i].points, m.items()[i].points);
  }
  auto error = [&](const char* text) {
    try {
      measurementsFromJson(nlohmann::json::parse(text), back);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(R"({"items":[{"kind":"circle","points":[]}]})").find("unknown kind 'circle'"),
            std::string::npos);
  EXPECT_NE(
      error(R"({"items":[{"kind":"angle","points":[[0,0,0],[1,1,1]]}]})").find("needs 3 points"),
      std::string::npos);
  EXPECT_NE(error(R"({"items":[{"kind":"distance","points":[[0,0],[1,1,1]]}]})").find("[i, j, k]"),
            std::string::npos);
  EXPECT_NE(
      error(R"({"items":[{"kind":"distance","normal_axis":"z","points":[]}]})").find("normal_axis"),
      std::string::npos);
  EXPECT_NE(error(R"({"items":[{"kind":7}]})").find("unknown kind"), std::string::npos);
  EXPECT_NE(error(R"({"items":[{"kind":"distance","points":[[1e300,0,0],[1,1,1]]}]})")
                .find("within +-1e6 voxels"),
            std::string::npos);
  EXPECT_NE(error(R"([1,2])").find("expected an object"), std::string::npos);
  EXPECT_EQ(back.items().size(), 4U);  // a bad file leaves the model as it was
}

TEST(Measure, ModelEditsKeepRoiInItsPlane) {
  MeasurementModel m;
  int changes = 0;
  m.changed.connect([&] { ++changes; });
  const int id = m.add(MeasureKind::Rect, {{1, 1, 4}, {3, 3, 4}}, 2);
  EXPECT_EQ(m.selected(), id);
  m.movePoint(id, 1, {6, 7, 9});  // a drag ending on another slice: stays on slice 4
  EXPECT_EQ(m.find(id)->points[1], glm::dvec3(6, 7, 4));
  m.remove(id);
  EXPECT_EQ(m.find(id), nullptr);
  EXPECT_EQ(m.selected(), 0);
  EXPECT_EQ(changes, 3);
}

// The 3D pick: the raycaster's first-hit output under a pixel, on the analytic sphere
// (radius 0.35 (n - 1) voxels), at the render parameters' defaults for iso.
TEST(Measure, PickedPointLiesOnTheSphereSurface) {
  const SyntheticSpec spec{SyntheticShape::Sphere, 48};
  const Volume v = makeSyntheticVolume(spec);
  ClContext ctx("cpu");
  Raycaster rc(ctx, v);
  RenderParams p;
  // Through the flags' own parser: the surface value 0, seen from the front left above.
  applyRenderValues(p, {{"mode", "iso"}, {"iso", "0"}, {"azimuth", "30"}, {"elevation", "20"}});
  p.width = 96;
  p.height = 72;
  std::vector<glm::vec4> hits;
  rc.renderWithHits(p, hits);
  const AnalyticField field{spec};
  // The sphere's outline on screen: the box of the pixels that hit.
  glm::ivec2 lo(p.width, p.height), hi(-1);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      if (surfaceHitAt(hits, {p.width, p.height}, {x, y})) {
        lo = glm::min(lo, glm::ivec2(x, y));
        hi = glm::max(hi, glm::ivec2(x, y));
      }
  ASSERT_GT(hi.x - lo.x, 20);
  const glm::ivec2 c = (lo + hi) / 2, r = (hi - lo) * 2 / 5;
  // The centre, and four pixels towards the rim, where rays meet the surface obliquely.
  int picked = 0;
  double worst = 0.0;
  for (glm::ivec2 pixel : {c, c + glm::ivec2(r.x, 0), c - glm::ivec2(r.x, 0),
                           c + glm::ivec2(0, r.y), c - glm::ivec2(0, r.y)}) {
    auto hit = surfaceHitAt(hits, {p.width, p.height}, pixel);
    ASSERT_TRUE(hit) << pixel.x << "," << pixel.y;
    EXPECT_LT(std::abs(field.surfaceDistance(*hit)), 0.05) << pixel.x << "," << pixel.y;
    worst = std::max(worst, std::abs(field.surfaceDistance(*hit)));
    ++picked;
  }
  RecordProperty("worst_surface_distance_voxels", std::to_string(worst));
  EXPECT_EQ(picked, 5);
  EXPECT_FALSE(surfaceHitAt(hits, {p.width, p.height}, {1, 1}));    // background: no surface
  EXPECT_FALSE(surfaceHitAt(hits, {p.width, p.height}, {96, 10}));  // outside the frame
  // Two picks make a distance in mm (1 mm voxels): the model keeps the first pending.
  MeasurementModel m;
  EXPECT_FALSE(m.addPick(*surfaceHitAt(hits, {p.width, p.height}, c - glm::ivec2(r.x, 0))));
  EXPECT_TRUE(m.pendingPick());
  auto id = m.addPick(*surfaceHitAt(hits, {p.width, p.height}, c + glm::ivec2(r.x, 0)));
  ASSERT_TRUE(id);
  EXPECT_FALSE(m.pendingPick());
  EXPECT_EQ(m.find(*id)->normalAxis, -1);
  EXPECT_GT(distanceMm(v, m.find(*id)->points[0], m.find(*id)->points[1]), 5.0);
}

// dvr picks march at most half a voxel per step (the balanced preset's 1.5 voxels would
// move the point by up to a step); finer steps and iso frames are left as they are.
TEST(Measure, DvrPickFramesStepHalfAVoxelAtMost) {
  RenderParams p;
  p.mode = Mode::Dvr;
  p.stepMm = 1.5 * 0.7;
  EXPECT_EQ(pickFrameParams(p, 0.7).stepMm, 0.35);
  p.stepMm = 0.25 * 0.7;
  EXPECT_EQ(pickFrameParams(p, 0.7).stepMm, 0.25 * 0.7);
  p.stepMm = 0.0;  // half the smallest spacing already
  EXPECT_EQ(pickFrameParams(p, 0.7).stepMm, 0.0);
  p.mode = Mode::Iso;
  p.stepMm = 1.5 * 0.7;
  EXPECT_EQ(pickFrameParams(p, 0.7).stepMm, 1.5 * 0.7);
}

// A pick that finds nothing says why, by mode: mip has no pick point; dvr's needs rays to
// reach 50 % opacity, which early termination below it forbids.
TEST(Measure, PickMissSaysWhy) {
  RenderParams p;
  p.mode = Mode::Iso;
  EXPECT_EQ(pickMissMessage(p), "No surface under the cursor to measure on");
  p.mode = Mode::Dvr;
  EXPECT_EQ(pickMissMessage(p), "Nothing under the cursor reaches 50 % opacity to measure on");
  p.earlyTermination = 0.3;
  EXPECT_EQ(pickMissMessage(p),
            "Early termination stops rays at 30 % opacity, before the 50 % a 3D pick needs: "
            "raise it to measure in 3D");
  p.mode = Mode::Mip;
  EXPECT_NE(pickMissMessage(p).find("switch the mode to iso or dvr"), std::string::npos);
}
