// A 4D series in the workstation (issue 36): the play clock, the time point the document
// shows, which volumes stay uploaded, the time–intensity curve on the beating-sphere phantom
// (its radius known per phase), SUVbw in the probe and ROI text on the PET sphere phantom,
// and the session's time point and rate.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../io/test_support.h"
#include "app_models.h"
#include "measurement_model.h"
#include "session.h"
#include "session_state.h"
#include "slice_image.h"
#include "status_text.h"
#include "study_state.h"
#include "time_series.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom_series.h"

namespace voxray {
namespace {

// A small beating sphere: 10 phases, radius 12 + 4 sin(2 pi t / 10) mm on 1.5 mm voxels.
BeatingSpherePhantom smallBeat() {
  BeatingSpherePhantom p;
  p.dims = {32, 32, 16};
  p.spacingMm = {1.5, 1.5, 3.0};
  p.radiusMm = 12.0;
  p.amplitudeMm = 4.0;
  return p;
}

VolumeSeries loadSeries(const std::string& dir) {
  VolumeSeries out;
  for (Volume& v : loadVolumeSeries(dir))
    out.push_back(std::make_shared<const Volume>(std::move(v)));
  return out;
}

// Distance of voxel (i, j, k)'s centre from the volume's centre in mm, as the phantom has it.
double fromCentre(const BeatingSpherePhantom& p, glm::ivec3 ijk) {
  return glm::length((glm::dvec3(ijk) - 0.5 * glm::dvec3(p.dims - 1)) * p.spacingMm);
}

TEST(TimePlayer, StepsAtTheFrameRateAndLoops) {
  TimePlayer player;
  player.setFps(4.0);                  // a point every 0.25 s
  EXPECT_EQ(player.tick(5.0, 10), 0);  // not playing: where it is
  player.play(3, 100.0);
  EXPECT_TRUE(player.playing());
  EXPECT_EQ(player.tick(100.0, 10), 3);
  EXPECT_EQ(player.tick(100.249, 10), 3);
  EXPECT_EQ(player.tick(100.25, 10), 4);  // exactly one frame later
  EXPECT_EQ(player.tick(101.0, 10), 7);   // a late tick skips to the right point
  EXPECT_EQ(player.tick(101.75, 10), 0);  // 3 + 7 = 10: looped to the first
  EXPECT_EQ(player.tick(104.25, 10), 0);  // 3 + 17 = 20: twice round
  EXPECT_EQ(player.tick(104.5, 10), 1);
  // A new rate restarts the clock at the point shown: no jump.
  player.setFps(2.0, 1, 104.5);
  EXPECT_EQ(player.tick(104.99, 10), 1);
  EXPECT_EQ(player.tick(105.0, 10), 2);
  EXPECT_TRUE(player.playing());
}

TEST(TimePlayer, WithoutLoopStopsOnTheLastPoint) {
  TimePlayer player;
  player.setLoop(false);
  player.setFps(10.0);
  int notified = 0;
  player.changed.connect([&] { ++notified; });
  player.play(7, 0.0);
  EXPECT_EQ(player.tick(0.15, 10), 8);
  EXPECT_EQ(player.tick(0.35, 10), 9);  // 7 + 3 = 10: past the end
  EXPECT_FALSE(player.playing());
  EXPECT_EQ(notified, 2);              // play, then the stop
  EXPECT_EQ(player.tick(9.0, 10), 9);  // stays there
}

TEST(TimePlayer, FpsIsClampedToWhatTheBoxOffers) {
  TimePlayer player;
  player.setFps(1000.0);
  EXPECT_EQ(player.fps(), TimePlayer::kMaxFps);
  player.setFps(0.0);
  EXPECT_EQ(player.fps(), TimePlayer::kMinFps);
  player.setFps(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(player.fps(), TimePlayer::kDefaultFps);
}

TEST(VolumeResidency, KeepsTheMostRecentlyShownWithinTheBudget) {
  int a, b, c, d;  // keys: any distinct addresses
  VolumeResidency r(300);
  EXPECT_TRUE(r.use(&a, 100).upload);
  EXPECT_TRUE(r.use(&b, 100).upload);
  EXPECT_TRUE(r.use(&c, 100).upload);
  EXPECT_EQ(r.residentBytes(), 300u);
  auto again = r.use(&a, 100);  // back to a: resident, nothing to upload
  EXPECT_FALSE(again.upload);
  EXPECT_TRUE(again.evict.empty());
  auto next = r.use(&d, 100);  // b was shown least recently: it goes
  EXPECT_TRUE(next.upload);
  ASSERT_EQ(next.evict.size(), 1u);
  EXPECT_EQ(next.evict[0], &b);
  EXPECT_FALSE(r.resident(&b));
  EXPECT_TRUE(r.resident(&a) && r.resident(&c) && r.resident(&d));
  // One volume over the budget is still shown (and everything else released).
  int big;
  auto huge = r.use(&big, 1000);
  EXPECT_EQ(huge.evict.size(), 3u);
  EXPECT_TRUE(r.resident(&big));
  EXPECT_EQ(r.residentBytes(), 1000u);
}

TEST(VolumeResidency, UploadsAheadOnlyWhatFitsBesideTheShown) {
  int shown, next, later, last;
  VolumeResidency r(300);
  EXPECT_TRUE(r.use(&shown, 100).upload);
  EXPECT_FALSE(r.preload(&shown, 100));  // resident already
  EXPECT_TRUE(r.preload(&next, 100));
  EXPECT_TRUE(r.preload(&later, 100));
  EXPECT_FALSE(r.preload(&last, 100));  // 400 > 300: left for its switch
  EXPECT_FALSE(r.resident(&last));
  // Switching to one uploaded ahead uploads nothing and releases nothing.
  auto use = r.use(&next, 100);
  EXPECT_FALSE(use.upload);
  EXPECT_TRUE(use.evict.empty());
  // One that failed to upload ahead is forgotten: its switch uploads it.
  r.forget(&later);
  EXPECT_TRUE(r.use(&later, 100).upload);
}

TEST(VolumeResidency, CpuKeepsEveryTimePointAGpuHalfItsMemory) {
  EXPECT_EQ(residencyBudget(false, size_t(4) << 30), std::numeric_limits<size_t>::max());
  EXPECT_EQ(residencyBudget(true, size_t(80) << 30), size_t(40) << 30);
  // 10 phases of 512x512x256 (128 MiB each, 1.25 GiB) fit an 80 GiB GPU's budget. A 2 GiB
  // GPU's 1 GiB holds 8 of them, the 8 shown last: playing in order then finds the next
  // phase always just released, and every switch uploads (what it does when they do not fit).
  const size_t phase = size_t(512) * 512 * 256 * 2;
  std::vector<int> keys(10);
  VolumeResidency big(residencyBudget(true, size_t(80) << 30));
  int uploads = 0;
  for (int round = 0; round < 2; ++round)
    for (int& k : keys) uploads += big.use(&k, phase).upload;
  EXPECT_EQ(uploads, 10);  // once each
  EXPECT_EQ(big.residentBytes(), 10 * phase);
  VolumeResidency small(residencyBudget(true, size_t(2) << 30));
  uploads = 0;
  for (int round = 0; round < 2; ++round)
    for (int& k : keys) uploads += small.use(&k, phase).upload;
  EXPECT_EQ(uploads, 20);
  EXPECT_EQ(small.residentBytes(), 8 * phase);
}

class BeatingSeries : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir;
    writeBeatingSpherePhantom(dir_->file("beat"), smallBeat());
    series_ = new VolumeSeries(loadSeries(dir_->file("beat")));
  }
  static void TearDownTestSuite() {
    delete series_;
    delete dir_;
  }
  static test::TempDir* dir_;
  static VolumeSeries* series_;
};
test::TempDir* BeatingSeries::dir_ = nullptr;
VolumeSeries* BeatingSeries::series_ = nullptr;

TEST_F(BeatingSeries, TimePointSwitchShowsThatPhasesVolume) {
  ASSERT_EQ(series_->size(), 10u);
  AppModels m;
  openStudy(m, *series_, "beat", {}, 4);
  EXPECT_EQ(m.document.timePoint(), 4);
  EXPECT_EQ(m.document.volume(), (*series_)[4]);
  int studies = 0, times = 0;
  m.document.changed.connect([&] { ++studies; });
  m.document.timeChanged.connect([&] { ++times; });
  const BeatingSpherePhantom p = smallBeat();
  const int k = p.dims.z / 2;  // the middle slice, its sphere cross-section per phase
  for (int t : {0, 2, 5, 7, 9, 1}) {
    SCOPED_TRACE(t);
    ASSERT_TRUE(m.document.setTimePoint(t));
    const Volume& v = *m.document.volume();
    EXPECT_EQ(m.document.volume(), (*series_)[size_t(t)]);
    EXPECT_EQ(v.timePoint, t);
    size_t bright = 0, expected = 0;
    for (int j = 0; j < v.dims.y; ++j)
      for (int i = 0; i < v.dims.x; ++i) {
        bright += v.toPhysical(v.at(i, j, k)) > 100.0;
        expected += fromCentre(p, {i, j, k}) <= p.radiusAt(t);
      }
    EXPECT_EQ(bright, expected);  // exact: the phantom writes inside <= r
  }
  EXPECT_EQ(times, 6);
  EXPECT_EQ(studies, 0);                      // same study: measurements and views stay
  EXPECT_FALSE(m.document.setTimePoint(1));   // already shown
  EXPECT_FALSE(m.document.setTimePoint(10));  // out of range
  EXPECT_FALSE(m.document.setTimePoint(-1));
  EXPECT_EQ(m.document.timePoint(), 1);
}

TEST_F(BeatingSeries, TimeIntensityCurveIsThePhantomsValuePerPhase) {
  const BeatingSpherePhantom p = smallBeat();
  // The centre voxel is inside at every phase; a voxel 11.4 mm out (i = 23 of 32 spacing
  // 1.5 mm: 7.5 voxels) is inside only while the radius (8 ... 16 mm) reaches it.
  const glm::ivec3 centre{16, 16, 8}, out{23, 16, 8};
  const auto atCentre = timeIntensityAtVoxel(*series_, glm::dvec3(centre));
  const auto atOut = timeIntensityAtVoxel(*series_, glm::dvec3(out));
  ASSERT_EQ(atOut.size(), 10u);
  int insideOut = 0;
  for (int t = 0; t < 10; ++t) {
    SCOPED_TRACE(t);
    const double c = fromCentre(p, centre) <= p.radiusAt(t) ? p.insideHu : p.outsideHu;
    const bool in = fromCentre(p, out) <= p.radiusAt(t);
    insideOut += in;
    EXPECT_EQ(atCentre[size_t(t)], c);
    EXPECT_EQ(atOut[size_t(t)], in ? p.insideHu : p.outsideHu);
  }
  EXPECT_GT(insideOut, 0);  // the voxel is crossed both ways: the curve is not flat
  EXPECT_LT(insideOut, 10);
  // An ROI inside the smallest sphere (radius 8 mm: a 6 x 6 mm square about the centre):
  // its mean is the inside value at every phase. Outside the volume: NaN.
  Measurement roi;
  roi.kind = MeasureKind::Rect;
  roi.normalAxis = 2;
  roi.points = {{13.5, 13.5, 8.0}, {17.5, 17.5, 8.0}};
  for (double mean : timeIntensityInRoi(*series_, roi)) EXPECT_EQ(mean, p.insideHu);
  for (double v : timeIntensityAtVoxel(*series_, {-5.0, 0.0, 0.0})) EXPECT_TRUE(std::isnan(v));
}

TEST(TimeIntensityCsv, OneLinePerTimePointWithTheUnit) {
  const std::vector<double> values{300.0, -50.0, std::numeric_limits<double>::quiet_NaN(), 6.6074};
  EXPECT_EQ(timeIntensityCsv(values, "crosshair [1, 2, 3]", "HU"),
            "time_point,crosshair [1, 2, 3] (HU)\n0,300\n1,-50\n2,\n3,6.6074\n");
}

TEST(TimeSession, KeepsTheTimePointAndRate) {
  test::TempDir dir;
  writeBeatingSpherePhantom(dir.file("beat"), smallBeat());
  AppModels m;
  openStudy(m, loadSeries(dir.file("beat")), "beat", {}, 0);
  m.source.path = dir.file("beat");
  m.document.setTimePoint(6);
  m.player.setFps(2.5);
  const Session s = sessionFromModels(m, {200, 150}, "grid");
  ASSERT_TRUE(s.time);
  EXPECT_EQ(s.input.flags.at("time"), "6");  // voxray-cli render --session: the same phase
  const std::string path = dir.file("s.json");
  writeSessionFile(path, s, false);
  const SessionRead read = readSessionFile(path);
  ASSERT_TRUE(read.session.time);
  EXPECT_EQ(read.session.time->point, 6);
  EXPECT_EQ(read.session.time->fps, 2.5);
  EXPECT_TRUE(read.warnings.empty());
  AppModels back;
  openStudy(back, loadSeries(dir.file("beat")), "beat", {}, 0);
  applySession(back, read.session);
  EXPECT_EQ(back.document.timePoint(), 6);
  EXPECT_EQ(back.document.volume()->timePoint, 6);
  EXPECT_EQ(back.player.fps(), 2.5);
  // A 3D volume's session has no time section.
  AppModels flat;
  openStudy(flat, back.document.series()[0], "one");
  EXPECT_FALSE(sessionFromModels(flat, {200, 150}, "grid").time);
}

TEST(TimeSession, ABadRateNamesTheField) {
  const std::string json = R"({"voxray-session": 1, "input": {"path": ""},
    "render": {}, "quality": {"preset": "balanced", "resolution": [0, 0]},
    "slices": {"window-width": 400, "window-level": 40, "crosshair": [0, 0, 0], "interp": "linear"},
    "layout": "grid", "time": {"point": 2, "fps": 500}})";
  try {
    sessionFromJson(json, "s.json");
    FAIL() << "fps 500 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("time.fps"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.5 ... 60"), std::string::npos) << e.what();
  }
}

// The PET sphere phantom: 21000 Bq/mL inside, SUVbw 6.607 (the CLI's figure, from the
// phantom's own weight, dose and decay: petSphereSuv).
TEST(SuvReadout, ProbeAndRoiReadSuvbwWithItsUnit) {
  test::TempDir dir;
  const PetSpherePhantom p;
  writePetSpherePhantom(dir.file("pet"), p);
  const Volume v = loadVolume(dir.file("pet"));
  ASSERT_TRUE(v.suv);
  const glm::dvec3 centre = 0.5 * glm::dvec3(v.dims - 1);
  const CursorProbe probe = probeAt(v, centre, Interp::Nearest);
  EXPECT_EQ(probe.unit, "SUVbw");
  EXPECT_NEAR(probe.value, petSphereSuv(p), 1e-9 * petSphereSuv(p));  // one product in double
  EXPECT_NEAR(probe.value, 6.607, 5e-4);
  const std::string text = formatCursorProbe(probe);
  EXPECT_EQ(text.substr(0, text.find("  [")), "6.607 SUVbw") << text;
  Measurement roi;  // a 12 x 12 mm square in the sphere (radius 36 mm) at its centre slice
  roi.kind = MeasureKind::Rect;
  roi.normalAxis = 2;
  roi.points = {centre - glm::dvec3(1.5, 1.5, 0.0), centre + glm::dvec3(1.5, 1.5, 0.0)};
  const std::string stats = measurementText(v, roi);
  EXPECT_NE(stats.find("SUVmean 6.607  SD 0.000  min 6.607  SUVmax 6.607  SUVpeak 6.607 SUVbw"),
            std::string::npos)
      << stats;
}

TEST(SuvReadout, WithoutTheWeightValuesStayInBqPerMlAndSayWhy) {
  test::TempDir dir;
  PetSpherePhantom p;
  p.omit = {"PatientWeight"};
  writePetSpherePhantom(dir.file("pet"), p);
  const Volume v = loadVolume(dir.file("pet"));
  EXPECT_FALSE(v.suv);
  const CursorProbe probe = probeAt(v, 0.5 * glm::dvec3(v.dims - 1), Interp::Nearest);
  EXPECT_EQ(probe.unit, "Bq/mL");
  const std::string text = formatCursorProbe(probe);
  EXPECT_EQ(text.substr(0, text.find("  [")), "21000 Bq/mL") << text;
  bool said = false;
  for (const auto& w : v.warnings) said |= w.find("Patient") != std::string::npos;
  EXPECT_TRUE(said) << "no warning names the missing weight";
}

}  // namespace
}  // namespace voxray
