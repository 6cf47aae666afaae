// Cine frames (engine/src/movie.cpp, cine_plane.cpp) against CThead's voxels, and the
// writing loop's cancel: what File > Export movie and voxray-cli movie share.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "accuracy_cthead.h"
#include "movie.h"
#include "movie_export.h"
#include "render_state_model.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

namespace voxray::test {
namespace {

namespace fs = std::filesystem;

constexpr double kWidth = 2000.0, kLevel = 500.0;

int expectedGrey(const Volume& v, int i, int j, int k) {
  const double hu = v.toPhysical(v.at(i, j, k));
  return int(std::clamp((hu - (kLevel - kWidth / 2)) / kWidth * 255.0 + 0.5, 0.0, 255.0));
}

MoviePlan cine(Orientation view, int frames) {
  MoviePlan plan;
  plan.cine = true;
  plan.view = view;
  plan.frames = frames;
  plan.params.width = plan.params.height = 0;
  plan.window = {kWidth, kLevel};
  return plan;
}

// Tolerance 1 grey level: the sample points go through the direction matrix and land on
// voxel centres only to about 1e-13 voxels, so a value may round to the neighbouring level.
constexpr int kLevels = 1;

TEST(MovieCine, AxialFramesAreTheSlicesInOrderWithThePatientsLeftOnTheRight) {
  const Volume* v = cthead();
  if (!v) GTEST_SKIP() << "shared CThead not found";
  MoviePlan plan = cine(Orientation::Axial, 3);
  settleMovieSize(plan, *v, MovieFormat::ImageSequence);
  MovieFrames frames(*v, nullptr, plan);
  ASSERT_EQ(frames.count(), 3);
  ASSERT_EQ(frames.size().width, 256);
  ASSERT_EQ(frames.size().height, 256);
  const int slices[] = {0, 56, 112};  // three spread over 113, first to last
  for (int f = 0; f < 3; ++f) {
    const Image img = frames.frame(f);
    int worst = 0;
    // CThead is LPI: i runs to the patient's left (the screen's right), j to posterior (down).
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x)
        worst = std::max(worst, std::abs(img.pixel(x, y)[0] - expectedGrey(*v, x, y, slices[f])));
    EXPECT_LE(worst, kLevels) << "frame " << f;
  }
}

TEST(MovieCine, CoronalAndSagittalFramesHaveSuperiorAtTheTop) {
  const Volume* v = cthead();
  if (!v) GTEST_SKIP() << "shared CThead not found";
  for (Orientation view : {Orientation::Coronal, Orientation::Sagittal}) {
    MoviePlan plan = cine(view, 0);
    settleMovieSize(plan, *v, MovieFormat::ImageSequence);
    MovieFrames frames(*v, nullptr, plan);
    EXPECT_EQ(frames.count(), 256);  // every slice along j (coronal) or i (sagittal)
    // 113 slices of 2 mm on 1 mm pixels: 226 rows.
    ASSERT_EQ(frames.size().width, 256);
    ASSERT_EQ(frames.size().height, 226);
    const int slice = 128;
    const Image img = frames.frame(slice);
    // Row 0 lies in the top half of slice k = 0 (superior: LPI), the last row in k = 112;
    // there the trilinear reconstruction repeats the edge voxel, so the values are exact.
    int worst = 0;
    for (int x = 0; x < 256; ++x)
      for (auto [row, k] : {std::pair{0, 0}, std::pair{225, 112}}) {
        const int i = view == Orientation::Coronal ? x : slice;
        const int j = view == Orientation::Coronal ? slice : x;  // sagittal: posterior right
        worst = std::max(worst, std::abs(img.pixel(x, row)[0] - expectedGrey(*v, i, j, k)));
      }
    EXPECT_LE(worst, kLevels) << (view == Orientation::Coronal ? "coronal" : "sagittal");
  }
}

TEST(MovieCine, AnotherAspectIsLetterboxedNotStretched) {
  const Volume v = makeHeadPhantom(32);  // a cube: square slices
  MoviePlan plan = cine(Orientation::Axial, 1);
  plan.params.width = 64;
  plan.params.height = 32;
  MovieFrames frames(v, nullptr, plan);
  const Image img = frames.frame(0);
  ASSERT_EQ(img.width, 64);
  // The slice fills the middle 32 columns; 16 black columns on each side.
  for (int y = 0; y < 32; ++y) {
    EXPECT_EQ(img.pixel(0, y)[0], 0);
    EXPECT_EQ(img.pixel(15, y)[0], 0);
    EXPECT_EQ(img.pixel(63, y)[0], 0);
  }
  EXPECT_GT(img.pixel(32, 16)[0], 0);  // the phantom's brain at the centre
}

class TempFolder {
 public:
  TempFolder() {
    std::random_device seed;
    path_ = fs::temp_directory_path() / ("voxray-movie-test-" + std::to_string(seed()));
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

TEST(MovieWrite, CancelLeavesNothingUnderTheFinalNames) {
  const Volume v = makeHeadPhantom(32);
  for (const std::string name : {"cine.mp4", "frames/"}) {
    TempFolder dir;
    std::atomic<bool> cancel{false};
    int reported = 0;
    MoviePlan plan = cine(Orientation::Axial, 8);
    plan.params.width = plan.params.height = 32;
    MovieFrames sized(v, nullptr, plan);
    try {
      writeMovie(
          sized, (dir.path() / name).string(), {},
          [&](const MovieProgress& p) {
            reported = p.done;
            EXPECT_EQ(p.total, 8);
            if (p.done == 3) cancel = true;
          },
          &cancel);
      FAIL() << "not cancelled";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << e.what();
    }
    EXPECT_EQ(reported, 3);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 0) << name;
  }
}

TEST(MovieWrite, ProgressEstimatesTheTimeLeftFromTheFramesSoFar) {
  const Volume v = makeHeadPhantom(32);
  TempFolder dir;
  MoviePlan plan = cine(Orientation::Sagittal, 4);
  plan.params.width = plan.params.height = 32;
  MovieFrames frames(v, nullptr, plan);
  std::vector<MovieProgress> seen;
  writeMovie(frames, (dir.path() / "s.mp4").string(), {},
             [&](const MovieProgress& p) { seen.push_back(p); });
  ASSERT_EQ(seen.size(), 5u);  // before the first frame, then after each
  for (size_t i = 1; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].done, int(i));
    EXPECT_NEAR(seen[i].leftS, seen[i].elapsedS / double(i) * double(4 - int(i)), 1e-9);
  }
  EXPECT_EQ(seen.back().leftS, 0.0);
  EXPECT_TRUE(fs::is_regular_file(dir.path() / "s.mp4"));
}

// Issue 41 item 8: the workstation's orbit started from the front whatever the view showed,
// and by default lasted 12 frames at 25 fps (0.48 s).
TEST(MovieOrbit, TheWorkstationsOrbitStartsFromTheViewsCamera) {
  const Volume v = makeHeadPhantom(16);
  RenderStateModel view;
  view.update(kCamera, [](RenderParams& p) {
    p.camera.azimuthDeg = 40.0;
    p.camera.elevationDeg = 20.0;
  });
  MovieChoice choice;
  EXPECT_EQ(choice.frames, 72);  // one turn in 3 s
  EXPECT_EQ(choice.fps, 24.0);
  MoviePlan azimuth = planMovie(choice, view, {}, v, "orbit.mp4");
  const CameraParams first = orbitFrameCamera(azimuth, 0, 72);
  EXPECT_EQ(first.azimuthDeg, 40.0);
  EXPECT_EQ(first.elevationDeg, 20.0);
  const CameraParams quarter = orbitFrameCamera(azimuth, 18, 72);
  EXPECT_EQ(quarter.azimuthDeg, 130.0);
  EXPECT_EQ(quarter.elevationDeg, 20.0);

  choice.kind = 1;  // over the top, at the view's azimuth
  MoviePlan elevation = planMovie(choice, view, {}, v, "orbit.mp4");
  EXPECT_EQ(orbitFrameCamera(elevation, 0, 72).elevationDeg, 20.0);
  EXPECT_EQ(orbitFrameCamera(elevation, 18, 72).elevationDeg, 110.0);
  EXPECT_EQ(orbitFrameCamera(elevation, 18, 72).azimuthDeg, 40.0);

  // voxray-cli's plan (orbitFromView off) keeps the fixed orbit that `bench` times.
  azimuth.orbitFromView = false;
  EXPECT_EQ(orbitFrameCamera(azimuth, 18, 72).azimuthDeg, 90.0);
  EXPECT_EQ(orbitFrameCamera(azimuth, 18, 72).elevationDeg, 20.0);
}

}  // namespace
}  // namespace voxray::test
