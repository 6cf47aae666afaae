// A 4D overlay and a 4D prior beyond their first time point (issue 36), on the beating-sphere
// phantom (phase t: a sphere of radius 24 + 8 sin(2 pi t / phases) mm, 300 HU inside, -50
// outside). The rule (time_follow.h): both 4D with as many time points, the overlay or prior
// follows the study's time point; otherwise it keeps its own, which a session keeps.
#include <gtest/gtest.h>

#include <filesystem>

#include "../io/test_support.h"
#include "app_models.h"
#include "fusion.h"
#include "session.h"
#include "session_state.h"
#include "time_follow.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom_series.h"

namespace voxray {
namespace {

// The phantom of PHASES phases written and read back, every time point.
VolumeSeries beating(const test::TempDir& dir, const std::string& name, int phases) {
  BeatingSpherePhantom p;
  p.phases = phases;
  writeBeatingSpherePhantom(dir.file(name), p);
  VolumeSeries out;
  for (Volume& v : loadVolumeSeries(dir.file(name)))
    out.push_back(std::make_shared<const Volume>(std::move(v)));
  return out;
}

// The centre of voxel (49, 31, 15) of the 64 x 64 x 32 phantom (1.5 x 1.5 x 3 mm): 26.30 mm
// from the sphere's centre, inside at the phases whose radius reaches it.
glm::dvec3 probeVoxel() { return {49, 31, 15}; }

double distanceFromCentre(const BeatingSpherePhantom& p) {
  return glm::length((probeVoxel() - 0.5 * glm::dvec3(p.dims - 1)) * p.spacingMm);
}

// What phase T of P holds at the probe: exact, the voxel's own value (the phantom writes 300
// where the voxel centre is within the radius).
double expectedAt(const BeatingSpherePhantom& p, int t) {
  return distanceFromCentre(p) <= p.radiusAt(t) ? 300.0 : -50.0;
}

// The fused value at the probe's patient point (a voxel centre: trilinear gives it exactly).
double fusedAt(const FusionModel& f) {
  const Volume& o = *f.overlay();
  PlaneGrid g;
  g.originMm = o.originMm + o.direction * (probeVoxel() * o.spacingMm);
  g.size = {1, 1};
  return double(fusionValues(o, g)[0]);
}

TEST(FusionTime, TheOverlayFollowsTheStudysPhaseWhenBothHaveAsMany) {
  test::TempDir dir;
  const VolumeSeries study = beating(dir, "study", 10), overlay = beating(dir, "overlay", 10);
  BeatingSpherePhantom p;
  ASSERT_GT(distanceFromCentre(p), p.radiusAt(0));  // outside at phase 0, inside at phase 2
  ASSERT_LT(distanceFromCentre(p), p.radiusAt(2));
  FusionModel f;
  f.setMainTime(0, 10);
  f.setOverlaySeries(overlay, "beating", study.front().get());
  EXPECT_TRUE(f.time().follows());
  int told = 0;
  f.changed.connect([&] { ++told; });
  int inside = 0;
  for (int t : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 3, 0}) {
    f.setMainTime(t, 10);
    EXPECT_EQ(f.time().shown(), t);
    EXPECT_EQ(f.overlay(), overlay[size_t(t)]);
    EXPECT_EQ(fusedAt(f), expectedAt(p, t)) << "phase " << t;
    inside += fusedAt(f) == 300.0;
  }
  EXPECT_EQ(inside, 5);  // phases 1 ... 4 (radius 28.7 ... 31.6 mm), and 3 again
  EXPECT_EQ(told, 11);   // each new phase once (phase 0 again from 3 included)
  f.setMainTime(0, 10);  // the same phase: nothing to tell
  EXPECT_EQ(told, 11);
  // The user's own choice waits while it follows.
  f.setOwnTimePoint(7);
  EXPECT_EQ(f.time().shown(), 0);
}

TEST(FusionTime, OtherCountsOrA3dStudyKeepTheOverlaysOwnTimePoint) {
  test::TempDir dir;
  const VolumeSeries overlay = beating(dir, "overlay", 5);
  BeatingSpherePhantom p5;
  p5.phases = 5;  // radius 24, 31.6, 28.7, 19.3, 16.4 mm
  FusionModel f;
  f.setMainTime(0, 10);
  f.setOverlaySeries(overlay, "beating 5", nullptr);
  EXPECT_FALSE(f.time().follows());
  for (int t = 0; t < 10; ++t) {
    f.setMainTime(t, 10);
    EXPECT_EQ(f.time().shown(), 0);
    EXPECT_EQ(fusedAt(f), expectedAt(p5, 0));
  }
  f.setOwnTimePoint(1);
  EXPECT_EQ(f.overlay(), overlay[1]);
  EXPECT_EQ(fusedAt(f), 300.0);  // 31.6 mm reaches the probe (26.3 mm)
  EXPECT_EQ(fusedAt(f), expectedAt(p5, 1));
  f.setMainTime(6, 10);
  EXPECT_EQ(f.time().shown(), 1);
  f.setOwnTimePoint(99);  // clamped to the last
  EXPECT_EQ(f.time().shown(), 4);
  // A 3D study: the overlay's own time point too.
  f.setMainTime(0, 1);
  EXPECT_FALSE(f.time().follows());
  EXPECT_EQ(f.time().shown(), 4);
  // A 3D overlay under a 4D study: its one volume.
  FusionModel single;
  single.setMainTime(3, 10);
  single.setOverlay(overlay[2], "one", nullptr);
  EXPECT_EQ(single.time().count(), 1);
  EXPECT_EQ(single.overlay(), overlay[2]);
}

TEST(FusionTime, TheOwnTimePointIsKeptInTheSession) {
  test::TempDir dir;
  const VolumeSeries overlay = beating(dir, "overlay", 5);
  AppModels m;
  m.fusion.setOverlaySeries(overlay, "beating 5", nullptr);
  m.fusion.setSource(dir.file("overlay"), {});
  m.fusion.setOwnTimePoint(3);
  const Session::Fusion saved = sessionFusion(m.fusion);
  EXPECT_EQ(saved.timePoint, 3);
  Session s;
  s.fusion = saved;
  s.comparison = Session::Comparison{dir.file("overlay"), std::nullopt, 2};
  const std::string file = dir.file("s.json");
  const SessionRead r = sessionFromJson(sessionToJson(s, file), file);
  ASSERT_TRUE(r.session.fusion && r.session.comparison);
  EXPECT_EQ(r.session.fusion->timePoint, 3);
  EXPECT_EQ(r.session.comparison->priorTimePoint, 2);
  EXPECT_TRUE(r.warnings.empty());
  AppModels again;
  again.fusion.setOverlaySeries(overlay, "beating 5", nullptr);
  EXPECT_TRUE(applySessionFusion(again.fusion, *r.session.fusion).empty());
  EXPECT_EQ(again.fusion.overlay(), overlay[3]);
  // A time point the overlay no longer has: its last, and said.
  Session::Fusion far = saved;
  far.timePoint = 8;
  const auto problems = applySessionFusion(again.fusion, far);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0],
            "the overlay's time point 8 is beyond its 5 time point(s): its last is shown");
  EXPECT_EQ(again.fusion.overlay(), overlay[4]);
  // A negative one in the file names the field.
  std::string json = sessionToJson(s, file);
  json.replace(json.find("\"time-point\": 3"), 15, "\"time-point\": -1");
  try {
    sessionFromJson(json, file);
    ADD_FAILURE() << "a negative time point was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'fusion.time-point' must be a time point"),
              std::string::npos)
        << e.what();
  }
}

// The compare prior: its document shows the followed time point as the study's slider moves.
TEST(PriorTime, ThePriorFollowsTheStudysPhaseOrKeepsItsOwn) {
  test::TempDir dir;
  const VolumeSeries study = beating(dir, "study", 10), same = beating(dir, "prior", 10),
                     other = beating(dir, "prior5", 5);
  BeatingSpherePhantom p;
  VolumeDocument main, prior;
  main.setSeries(study, "study");
  prior.setSeries(same, "prior");
  TimeFollow follow;
  int told = 0;
  prior.timeChanged.connect([&] { ++told; });
  for (int t = 0; t < 10; ++t) {
    main.setTimePoint(t);
    showFollowedTime(prior, follow, main);
    EXPECT_EQ(prior.timePoint(), t);
    const Volume& v = *prior.volume();
    EXPECT_EQ(v.toPhysical(v.voxels[v.index(49, 31, 15)]), expectedAt(p, t)) << "phase " << t;
  }
  EXPECT_EQ(told, 9);
  // Five phases beside ten: its own time point, 0 until chosen.
  TimeFollow own;
  prior.setSeries(other, "prior 5");
  main.setTimePoint(6);
  showFollowedTime(prior, own, main);
  EXPECT_EQ(prior.timePoint(), 0);
  own.setOwn(2);
  showFollowedTime(prior, own, main);
  EXPECT_EQ(prior.timePoint(), 2);
  main.setTimePoint(1);
  showFollowedTime(prior, own, main);
  EXPECT_EQ(prior.timePoint(), 2);
}

}  // namespace
}  // namespace voxray
