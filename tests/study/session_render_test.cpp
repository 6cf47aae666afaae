// Issue 13, session files: a session saved from the workstation's models and rendered by
// `voxray-cli render --session` gives the 3D view's frame pixel for pixel; the workstation
// reopens it to the same state; moved data and a kept file are refused with what to do.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "../io/test_support.h"
#include "measurement_json.h"
#include "render_worker.h"
#include "session_state.h"
#include "study_state.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/image.h"
#include "voxray/io/load.h"

using namespace voxray;
namespace fs = std::filesystem;

namespace {

const std::string kCtHead = std::string(VOXRAY_DATA_DIR) + "/stanford/CThead";
const std::map<std::string, std::string> kCtHeadFlags = {
    {"raw-dims", "256,256"},  {"raw-type", "i16"},        {"raw-endian", "big"},
    {"raw-spacing", "1,1,2"}, {"raw-rescale", "1,-1024"}, {"raw-axes", "LPI"}};

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// voxray-cli ARGS with stderr into LOG; its exit status.
int runCli(const std::string& args, const std::string& log) {
  const std::string command = std::string("'") + VOXRAY_CLI + "' " + args + " 2> '" + log + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The 3D view's frame at rest for M's state at VIEWSIZE, rendered as the workstation does:
// planFrame (RenderScheduler::fullParams) on a RenderWorker.
Frame viewFrame(const AppModels& m, const glm::ivec2& viewSize) {
  std::mutex mutex;
  std::condition_variable done;
  std::shared_ptr<const Frame> frame;
  std::string error;
  RenderCallbacks callbacks;
  callbacks.frame = [&](std::shared_ptr<const Frame> f) {
    std::lock_guard lock(mutex);
    frame = std::move(f);
    done.notify_all();
  };
  callbacks.error = [&](const std::string& message, bool) {
    std::lock_guard lock(mutex);
    error = message;
    done.notify_all();
  };
  {
    RenderWorker worker("", callbacks);
    worker.setVolume(m.document.volume());
    worker.request(planFrame(m.render.params(), m.render.quality(), viewSize, false,
                             m.document.minSpacingMm()),
                   false);
    std::unique_lock lock(mutex);
    done.wait_for(lock, std::chrono::minutes(5), [&] { return frame || !error.empty(); });
  }
  EXPECT_EQ(error, "");
  return frame ? *frame : Frame{};
}

// CThead opened as the workstation opens it, then looked at the way a user would: a cut,
// an orbit (to angles no short decimal holds), a fixed light, a window and slice positions.
void openCtHeadAndLookAround(AppModels& m) {
  LoadOptions o = loadOptionsFromFlags(kCtHeadFlags);
  openStudy(m, std::make_shared<const Volume>(loadVolume(kCtHead, o)), "CThead");
  m.source = {kCtHead, kCtHeadFlags};
  m.render.applyPreset("CT-Bone");
  m.render.setPresetShift(-40.0);
  m.render.update(kCamera | kClip | kLight, [](RenderParams& p) {
    p.camera.azimuthDeg = 61.23456789012345;
    p.camera.elevationDeg = 17.0 / 3.0;
    p.camera.zoom = 1.2345678901234;
    p.camera.panMm = {3.0 / 7.0, -5.0};
    p.clip.lo = {0.0, 0.1, 0.05};
    p.clip.hi = {2.0 / 3.0, 1.0, 0.9};
    p.light.position = {150.0, -200.0 / 3.0, 80.0};
    p.light.followCamera = false;
  });
  m.windowLevel.set({1800.0, 400.0});
  m.crosshair.setVoxel({100, 140, 60});
  m.measurements.add(MeasureKind::Distance, {{10.5, 20.0, 60.0}, {110.0, 140.25, 60.0}}, 2);
  m.measurements.add(MeasureKind::Ellipse, {{90.0, 100.0, 60.0}, {120.0, 130.0, 60.0}}, 2);
}

size_t differingBytes(const Image& a, const Image& b) {
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.rgba.size(), b.rgba.size()); ++i) n += a.rgba[i] != b.rgba[i];
  return n;
}

}  // namespace

// Tolerance 0: the CLI and the view's RenderWorker run the same kernels on the same device
// (VOXRAY_DEVICE=cpu) with the same parameters, so equal images are the only right answer.
TEST(SessionRender, CliRendersTheViewsFramePixelForPixel) {
  test::TempDir dir;
  AppModels m;
  openCtHeadAndLookAround(m);
  const glm::ivec2 viewSize{208, 150};
  for (const char* quality : {"balanced", ""}) {  // a quality preset, then custom
    SCOPED_TRACE(std::string("quality '") + quality + "'");
    Quality q = m.render.quality();
    q.preset = quality;
    if (!*quality) q.resolution = {176, 132};  // a fixed resolution instead of the view's
    m.render.setQuality(q);
    if (!*quality) m.render.update(kAppearance, [](RenderParams& p) { p.jitter = true; });
    const Frame frame = viewFrame(m, viewSize);
    ASSERT_GT(frame.image.width, 0);

    const std::string session = dir.file(std::string("view-") + quality + ".json");
    writeSessionFile(session, sessionFromModels(m, viewSize, "3d"), false);
    const std::string out = dir.file(std::string("cli-") + quality + ".png");
    ASSERT_EQ(runCli("render --session '" + session + "' -o '" + out + "'", dir.file("log")), 0)
        << readText(dir.file("log"));
    const Image cli = readImage(out);
    ASSERT_EQ(cli.width, frame.image.width);
    ASSERT_EQ(cli.height, frame.image.height);
    EXPECT_EQ(differingBytes(cli, frame.image), 0u);
    // Not an empty picture: the cut skull covers a good part of the frame.
    size_t lit = 0;
    for (size_t i = 0; i < cli.rgba.size(); i += 4) lit += cli.rgba[i] + cli.rgba[i + 1] > 40;
    EXPECT_GT(lit, cli.rgba.size() / 4 / 10);
  }
}

TEST(SessionRender, ReopenedSessionRestoresTheModelsState) {
  test::TempDir dir;
  AppModels m;
  openCtHeadAndLookAround(m);
  Quality q = m.render.quality();
  q.preset = "reference";
  q.resolution = {320, 240};
  m.render.setQuality(q);
  m.render.setSliceInterp(Interp::Nearest);
  // Oblique and slab MPR: the axial view turned (the other two planes turn), a coronal slab.
  m.crosshair.rotateInView(sliceAxes(m.document.volume()->direction, Orientation::Axial), 0.3);
  m.crosshair.clickInView(sliceAxes(m.document.volume()->direction, Orientation::Coronal), 101.5,
                          33.25);  // off voxel centres, as a turned crosshair moves
  m.crosshair.setSlab(Orientation::Coronal, {15.0, SlabMode::MinIp});
  const glm::dvec3 centre = m.crosshair.centre();
  const std::string file = dir.file("a.json");
  writeSessionFile(file, sessionFromModels(m, {640, 480}, "coronal"), false);

  AppModels reopened;  // a fresh workstation: defaults everywhere
  const SessionRead read = readSessionFile(file);
  ASSERT_TRUE(read.missingInput.empty());
  openSession(reopened, m.document.volume(), "CThead", read.session);
  EXPECT_EQ(toText(reopened.render.params()), toText(m.render.params()));
  EXPECT_EQ(reopened.render.quality().preset, "reference");
  EXPECT_EQ(reopened.render.quality().resolution, glm::ivec2(320, 240));
  EXPECT_EQ(reopened.render.sliceInterp(), Interp::Nearest);
  EXPECT_EQ(reopened.windowLevel.value().width, 1800.0);
  EXPECT_EQ(reopened.windowLevel.value().level, 400.0);
  EXPECT_EQ(reopened.crosshair.centre(), centre);
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal}) {
    EXPECT_EQ(reopened.crosshair.rotation(o), m.crosshair.rotation(o)) << toString(o);
    EXPECT_EQ(reopened.crosshair.slab(o).thicknessMm, m.crosshair.slab(o).thicknessMm);
    EXPECT_EQ(reopened.crosshair.slab(o).mode, m.crosshair.slab(o).mode);
  }
  EXPECT_TRUE(reopened.crosshair.rotated());
  EXPECT_EQ(reopened.crosshair.slab(Orientation::Coronal).mode, SlabMode::MinIp);
  EXPECT_EQ(reopened.source.path, fs::absolute(kCtHead).lexically_normal().string());
  EXPECT_EQ(reopened.source.flags, kCtHeadFlags);
  EXPECT_EQ(measurementsToJson(reopened.measurements), measurementsToJson(m.measurements));
  EXPECT_EQ(reopened.measurements.items().size(), 2u);
  // Saved again, it is the same file.
  EXPECT_EQ(sessionToJson(sessionFromModels(reopened, {640, 480}, "coronal"), file),
            readText(file));
}

TEST(SessionRender, CliSaysWhereMovedDataWasLookedForAndTakesItsNewPlace) {
  test::TempDir dir;
  Session s;
  s.input = {(dir.path() / "gone" / "CThead").string(), kCtHeadFlags};
  s.render.width = 64;
  s.render.height = 48;
  const std::string session = dir.file("moved.json");
  writeSessionFile(session, s, false);
  const std::string out = dir.file("moved.png"), log = dir.file("log");
  EXPECT_EQ(runCli("render --session '" + session + "' -o '" + out + "'", log), 1);
  const std::string message = readText(log);
  EXPECT_NE(message.find("its data is missing (not at " + s.input.path + ")"), std::string::npos)
      << message;
  EXPECT_NE(message.find("give its new location as INPUT"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(out));
  // The new location as INPUT: rendered at the session's size.
  ASSERT_EQ(runCli("render '" + kCtHead + "' --session '" + session + "' -o '" + out + "'", log), 0)
      << readText(log);
  EXPECT_EQ(readImage(out).width, 64);
}

TEST(SessionRender, CliKeepsAnExistingSessionUnlessForced) {
  test::TempDir dir;
  const std::string session = dir.file("kept.json"), out = dir.file("x.png"), log = dir.file("log");
  std::ofstream(session) << "{}";
  const std::string args = "render --size 32x24 -o '" + out + "' --save-session '" + session + "'";
  EXPECT_EQ(runCli(args, log), 1);
  EXPECT_NE(readText(log).find("exists and is kept"), std::string::npos) << readText(log);
  EXPECT_EQ(readText(session), "{}");
  ASSERT_EQ(runCli(args + " --force", log), 0) << readText(log);
  const SessionRead read = readSessionFile(session);
  EXPECT_EQ(read.session.input.path, "");  // the embedded phantom
  EXPECT_EQ(read.session.render.width, 32);
}
