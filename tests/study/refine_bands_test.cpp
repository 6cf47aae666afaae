// Issue 16: the sharp frame after a drag in bands. The plan (which rows, in which order),
// the render worker following it (each band posted; a new camera abandons the bands left
// and is rendered next; an export lets them go on), the final frame pixel for pixel the
// directly rendered one, and the stall on the Session 5 timings.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "refine_bands.h"
#include "render_state_model.h"
#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/phantom.h"

using namespace voxray;

namespace {

TEST(RefineBands, TheWorkstationFrameComesInSixteenBandsMiddleFirst) {
  // 1024x768: 786432 pixels, 16 x 128x384; 48 blocks of 16 rows, 3 (48 rows) a band; the
  // middle (the eighth from the top) first, then below, above, below ...
  const std::vector<RowBand> b = refineBands(1024, 768);
  ASSERT_EQ(b.size(), 16u);
  const int order[16] = {7, 8, 6, 9, 5, 10, 4, 11, 3, 12, 2, 13, 1, 14, 0, 15};
  for (int i = 0; i < 16; ++i)
    EXPECT_EQ(b[size_t(i)], (RowBand{48 * order[i], 48 * order[i] + 48}));
  // A sixteenth of that or less: the frame whole.
  EXPECT_EQ(refineBands(128, 384), (std::vector<RowBand>{{0, 384}}));
  EXPECT_EQ(refineBands(1024, 768, 1), (std::vector<RowBand>{{0, 768}}));
  EXPECT_EQ(refineBands(1024, 768, 4, 512L * 384L),
            (std::vector<RowBand>{{192, 384}, {384, 576}, {0, 192}, {576, 768}}));
  EXPECT_TRUE(refineBands(0, 768).empty());
}

TEST(RefineBands, BandsTileTheFrameOnSixteenRowBoundaries) {
  for (auto [w, h] : {std::pair{1920, 1080}, {1530, 1040}, {800, 601}, {2000, 40}}) {
    std::vector<RowBand> b = refineBands(w, h);
    const size_t expected =
        std::min<size_t>({32, size_t((long(w) * h + kRefineBandPixels - 1) / kRefineBandPixels),
                          size_t((h + 15) / 16)});
    EXPECT_EQ(b.size(), expected) << w << "x" << h;
    std::sort(b.begin(), b.end(), [](RowBand a, RowBand c) { return a.y0 < c.y0; });
    int at = 0;
    for (const RowBand& r : b) {
      EXPECT_EQ(r.y0, at) << w << "x" << h;  // no gap, no overlap
      EXPECT_EQ(r.y0 % kRefineBandAlign, 0);
      EXPECT_GT(r.y1, r.y0);
      at = r.y1;
    }
    EXPECT_EQ(at, h);
    // Nearly equal: heights differ by at most one 16-row block (plus the last's remainder).
    int lo = h, hi = 0;
    for (const RowBand& r : b) lo = std::min(lo, r.y1 - r.y0), hi = std::max(hi, r.y1 - r.y0);
    EXPECT_LE(hi - lo, 16 + (16 - h % 16) % 16) << w << "x" << h;
  }
}

TEST(RefineBands, DragAndCinematicFramesAreWhole) {
  RenderParams p;
  p.width = 1024;
  p.height = 768;
  EXPECT_EQ(viewFrameBands(p, false).size(), 16u);
  EXPECT_TRUE(viewFrameBands(p, true).empty());
  p.lighting = Lighting::Cinematic;
  EXPECT_TRUE(viewFrameBands(p, false).empty());
}

TEST(RefineBands, TheSharpFrameAfterADragIsTheBalancedFrameInBands) {
  // What the scheduler asks for around a drag of a 1024x768 view (planFrame): drag frames
  // at half size and 2-voxel steps, then the balanced frame whole size at 1.5-voxel steps
  // in 16 bands. 0.5 mm voxels.
  RenderStateModel m;
  m.applyPreset("CT-Bone");
  Quality q = m.quality();
  q.preset = "balanced";
  m.setQuality(q);
  const RenderParams drag = planFrame(m.params(), m.quality(), {1024, 768}, true, 0.5);
  EXPECT_EQ(drag.width, 512);
  EXPECT_EQ(drag.height, 384);
  EXPECT_DOUBLE_EQ(drag.stepMm, 1.0);
  EXPECT_TRUE(viewFrameBands(drag, true).empty());
  const RenderParams sharp = planFrame(m.params(), m.quality(), {1024, 768}, false, 0.5);
  EXPECT_EQ(sharp.width, 1024);
  EXPECT_EQ(sharp.height, 768);
  EXPECT_DOUBLE_EQ(sharp.stepMm, 0.75);
  EXPECT_EQ(sharp.refine, 6);
  EXPECT_EQ(viewFrameBands(sharp, false).size(), 16u);
}

TEST(RefineBands, UpscaleNearestRepeatsEachPixel) {
  Image src(2, 2);
  for (int i = 0; i < 4; ++i) src.rgba[size_t(i) * 4] = uint8_t(10 * (i + 1));
  Image big = upscaleNearest(src, 4, 4);
  ASSERT_EQ(big.width, 4);
  const int expected[4][4] = {
      {10, 10, 20, 20}, {10, 10, 20, 20}, {30, 30, 40, 40}, {30, 30, 40, 40}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(big.pixel(x, y)[0], expected[y][x]) << x << "," << y;
  Image none = upscaleNearest(Image{}, 3, 2);  // nothing shown yet: black, opaque
  EXPECT_EQ(none.pixel(2, 1)[0], 0);
  EXPECT_EQ(none.pixel(2, 1)[3], 255);
}

// The scheduler and render worker on synthetic timings (a discrete-event model of their
// rules): the mouse moves every 16 ms until STOPMS, each move asks for a drag frame that
// replaces any request not started; SETTLEMS after the last move the sharp frame is asked
// for, whole or in refineBands (each band's cost its share of the rows); the mouse moves
// once more RESUMEMS after the refinement started (negative: never). Returns the largest gap
// between frames shown from the last drag frame to the sharp frame, and the wait from the resumed
// move to its frame.
struct StallModel {
  double dragMs, sharpMs, settleMs;
  bool bands;
};
struct StallResult {
  double restGapMs = 0, resumeWaitMs = 0;
};
StallResult simulateStall(const StallModel& m, double resumeMs) {
  const double stopMs = 992;  // the last of the moves every 16 ms
  // Drag frames back to back from 0: the last move is rendered by the first frame to start
  // after it (the one in flight keeps its camera).
  const double shown = std::ceil(stopMs / m.dragMs) * m.dragMs + m.dragMs;
  StallResult r;
  const double asked = stopMs + m.settleMs;
  std::vector<RowBand> bands = m.bands ? refineBands(1024, 768) : std::vector<RowBand>{{0, 768}};
  double at = std::max(asked, shown), last = shown;
  const double moved = at + resumeMs;  // the refinement has started
  for (const RowBand& b : bands) {
    at += m.sharpMs * (b.y1 - b.y0) / 768.0;
    r.restGapMs = std::max(r.restGapMs, at - last);
    last = at;
    if (resumeMs >= 0 && at >= moved) {  // the move waited for this band; the rest abandoned
      r.resumeWaitMs = at + m.dragMs - moved;
      break;
    }
  }
  return r;
}

TEST(RefineBands, TheStallOnSessionFiveTimings) {
  // Session 5 on the 512x512x400 CT at 16 lanes: a balanced frame 239 ms of kernel CPU, a
  // drag frame 75; on 2 idle cores about half as wall time: 120 and 38 ms.
  const StallModel before{38, 120, 150, false}, after{38, 120, 60, true};
  const StallResult b = simulateStall(before, -1), a = simulateStall(after, -1);
  // Before: the last drag frame 1 to 2 frames after the last move (the frame in flight
  // first), the settle to 150 ms, then the whole frame without a new one: 194 ... 270 ms.
  EXPECT_GE(b.restGapMs, 150 - 2 * 38 + 120 - 1e-9);
  EXPECT_LE(b.restGapMs, 150 + 120 + 1e-9);
  // After: the settle to 60 ms (here over before the last drag frame is shown), then a band
  // of 48 rows (7.5 ms) at a time.
  EXPECT_LE(a.restGapMs, 60 + 7.5 + 1e-9);
  EXPECT_LE(a.restGapMs, 0.4 * b.restGapMs);
  // A move 5 ms into the refinement: the whole frame's 115 ms left and its drag frame,
  // against the first band's 2.5 ms left.
  EXPECT_NEAR(simulateStall(before, 5).resumeWaitMs, 115 + 38, 1e-9);
  EXPECT_NEAR(simulateStall(after, 5).resumeWaitMs, 2.5 + 38, 1e-9);
}

// The frames a RenderWorker posts, its callbacks run on the render thread (no Post) so that
// a test can ask for the next frame from inside a band's callback, deterministically.
struct Recorder {
  std::mutex mutex;
  std::condition_variable arrived;
  std::vector<std::shared_ptr<const Frame>> frames;
  std::string error;
  std::function<void(const Frame&)> onFrame;  // runs on the render thread

  RenderCallbacks callbacks() {
    RenderCallbacks cb;
    cb.frame = [this](std::shared_ptr<const Frame> f) {
      if (onFrame) onFrame(*f);
      std::lock_guard lock(mutex);
      frames.push_back(std::move(f));
      arrived.notify_all();
    };
    cb.error = [this](const std::string& m, bool) {
      std::lock_guard lock(mutex);
      error = m;
      arrived.notify_all();
    };
    return cb;
  }
  // Waits for N frames; then a moment longer to see that no more come.
  void waitFor(size_t n) {
    std::unique_lock lock(mutex);
    arrived.wait_for(lock, std::chrono::minutes(3),
                     [&] { return frames.size() >= n || !error.empty(); });
    lock.unlock();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
};

RenderParams phantomFrame(double azimuth) {
  RenderParams p;
  p.mode = Mode::Dvr;
  p.width = 96;
  p.height = 80;
  p.camera.azimuthDeg = azimuth;
  p.gradient = Gradient::ZuckerHummel;
  return p;
}

const std::vector<RowBand> kBands = {{32, 64}, {64, 80}, {0, 32}};

TEST(RefineBandsWorker, TheFinalBandedFrameIsTheDirectFramePixelForPixel) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(64));
  const RenderParams p = phantomFrame(30.0);
  Image direct;
  {
    ClContext ctx("cpu");
    Raycaster rc(ctx, *volume);
    rc.render(p, direct);
    // Bands that do not start on a packet's row still give the direct frame's rows.
    Image rows = upscaleNearest(Image{}, p.width, p.height);
    for (RowBand b : {RowBand{0, 21}, RowBand{21, 50}, RowBand{50, 80}})
      rc.renderRows(p, rows, b.y0, b.y1);
    EXPECT_TRUE(rows.rgba == direct.rgba);
  }
  Recorder rec;
  RenderWorker worker("cpu", rec.callbacks());
  worker.setVolume(volume);
  worker.request(phantomFrame(90.0), true);  // a drag frame first: the bands paint over it
  rec.waitFor(1);
  worker.requestBands(p, kBands);
  rec.waitFor(4);
  ASSERT_EQ(rec.error, "");
  ASSERT_EQ(rec.frames.size(), 4u);
  for (int i = 1; i <= 3; ++i) {
    EXPECT_EQ(rec.frames[size_t(i)]->bandsDone, i);
    EXPECT_EQ(rec.frames[size_t(i)]->bands, 3);
    EXPECT_EQ(rec.frames[size_t(i)]->band, kBands[size_t(i - 1)]);
    EXPECT_FALSE(rec.frames[size_t(i)]->interactive);
  }
  const Image& final = rec.frames[3]->image;
  ASSERT_EQ(final.width, p.width);
  ASSERT_EQ(final.height, p.height);
  EXPECT_TRUE(final.rgba == direct.rgba) << "the last band's frame differs from render()";
  // After the first band, its rows are the sharp frame's and the rest is the drag frame's.
  const Image& partial = rec.frames[1]->image;
  EXPECT_TRUE(std::equal(partial.rgba.begin() + 32 * 96 * 4, partial.rgba.begin() + 64 * 96 * 4,
                         direct.rgba.begin() + 32 * 96 * 4));
  EXPECT_TRUE(std::equal(partial.rgba.begin(), partial.rgba.begin() + 32 * 96 * 4,
                         rec.frames[0]->image.rgba.begin()));
}

TEST(RefineBandsWorker, ANewCameraAbandonsTheBandsLeftAndIsRenderedNext) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(64));
  Recorder rec;
  RenderWorker* w = nullptr;
  bool moved = false;
  rec.onFrame = [&](const Frame& f) {
    if (f.bandsDone == 1 && !moved) {  // the camera moves while the first band is shown
      moved = true;
      w->request(phantomFrame(60.0), true);
    }
  };
  RenderWorker worker("cpu", rec.callbacks());
  w = &worker;
  worker.setVolume(volume);
  worker.requestBands(phantomFrame(30.0), kBands);
  rec.waitFor(2);
  ASSERT_EQ(rec.error, "");
  ASSERT_EQ(rec.frames.size(), 2u) << "bands of the old camera rendered after the move";
  EXPECT_EQ(rec.frames[0]->bandsDone, 1);
  EXPECT_EQ(rec.frames[0]->params.camera.azimuthDeg, 30.0);
  EXPECT_TRUE(rec.frames[1]->interactive);
  EXPECT_EQ(rec.frames[1]->params.camera.azimuthDeg, 60.0);
  EXPECT_EQ(rec.frames[1]->bands, 0);
}

TEST(RefineBandsWorker, AnExportGoesBetweenBandsAndTheBandsGoOn) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(64));
  Recorder rec;
  RenderWorker* w = nullptr;
  bool asked = false;
  rec.onFrame = [&](const Frame& f) {
    if (f.bandsDone == 1 && !asked) {
      asked = true;
      w->request(phantomFrame(45.0), false, 1);
    }
  };
  RenderWorker worker("cpu", rec.callbacks());
  w = &worker;
  worker.setVolume(volume);
  worker.requestBands(phantomFrame(30.0), kBands);
  rec.waitFor(4);
  ASSERT_EQ(rec.frames.size(), 4u);
  EXPECT_EQ(rec.frames[0]->bandsDone, 1);
  EXPECT_EQ(rec.frames[1]->tag, 1);
  EXPECT_EQ(rec.frames[2]->bandsDone, 2);
  EXPECT_EQ(rec.frames[2]->band, kBands[1]);
  EXPECT_EQ(rec.frames[3]->bandsDone, 3);
  EXPECT_EQ(rec.frames[3]->band, kBands[2]);
}

}  // namespace
