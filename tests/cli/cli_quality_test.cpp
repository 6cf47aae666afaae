// `voxray-cli render --quality X` against the workstation's frame at quality X (issue 39,
// defect 5): the workstation's quality box picks a preset into the render parameters
// (RenderStateModel::setQualityPreset: its reconstruction and gradient) and plans each
// frame at rest from them (planFrame: its step, refinement, jitter and image scale); the CLI
// must go the same way. PNG is lossless and both run the same kernels on the same device
// (VOXRAY_DEVICE=cpu), so the tolerance is 0.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "render_state_model.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/quality.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/image.h"
#include "voxray/io/sample_volume.h"

using namespace voxray;

namespace {

constexpr int kWidth = 96, kHeight = 72;

// voxray-cli render ARGS -o NAME.png in the build tree: the image (empty when it failed;
// stderr then in the test's output).
Image renderCli(const std::string& args, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(VOXRAY_CLI).parent_path().parent_path() / "tests/cli/quality";
  std::filesystem::create_directories(dir);
  const std::string png = (dir / (name + ".png")).string(), log = (dir / (name + ".log")).string();
  std::filesystem::remove(png);
  const int status = std::system((std::string("VOXRAY_DEVICE=cpu ") + VOXRAY_CLI + " render " +
                                  args + " -o " + png + " 2> " + log)
                                     .c_str());
  std::stringstream err;
  err << std::ifstream(log).rdbuf();
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  EXPECT_TRUE(ok) << err.str();
  return ok ? readImage(png) : Image{};
}

// The workstation's frame at rest for M's state, planned for a view whose frame at M's
// quality is kWidth x kHeight (the quality's image scale applied), rendered on the CPU.
Image workstationFrame(const RenderStateModel& m, const Volume& v) {
  const double scale = findQualityPreset(m.quality().preset).resolutionScale;
  const glm::ivec2 view(int(kWidth / scale + 0.5), int(kHeight / scale + 0.5));
  const RenderParams p = planFrame(m.params(), m.quality(), view, false, v.minSpacingMm());
  EXPECT_EQ(p.width, kWidth);
  EXPECT_EQ(p.height, kHeight);
  static ClContext cpu("cpu");
  Raycaster rc(cpu, v);
  return rc.render(p);
}

size_t differingBytes(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.rgba.size() != b.rgba.size()) return std::max(a.rgba.size(), b.rgba.size());
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) n += a.rgba[i] != b.rgba[i];
  return n;
}

const std::string kScene = std::string(kSampleCtInput) + " --mode dvr --preset CT-Bone " +
                           "--azimuth 30 --size " + std::to_string(kWidth) + "x" +
                           std::to_string(kHeight);

RenderStateModel sceneModel() {
  RenderStateModel m;
  m.applyPreset("CT-Bone");
  m.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 30.0; });
  return m;
}

}  // namespace

TEST(CliQuality, EachPresetRendersTheWorkstationsFramePixelForPixel) {
  const Volume v = loadSampleCt();
  for (const QualityPreset& q : builtinQualityPresets()) {
    SCOPED_TRACE("quality " + q.name);
    RenderStateModel m = sceneModel();
    m.setQualityPreset(q.name);  // the quality box's pick
    const Image cli = renderCli(kScene + " --quality " + q.name, "preset-" + q.name);
    EXPECT_EQ(differingBytes(cli, workstationFrame(m, v)), 0u);
  }
}

// A gradient given with the preset wins, as the Rendering group's does after a pick.
TEST(CliQuality, AGradientGivenWithThePresetWinsAsInTheWorkstation) {
  const Volume v = loadSampleCt();
  RenderStateModel m = sceneModel();
  m.setQualityPreset("reference");
  m.update(kAppearance, [](RenderParams& p) { p.gradient = Gradient::Central; });
  const Image cli =
      renderCli(kScene + " --quality reference --gradient central", "reference-central");
  EXPECT_EQ(differingBytes(cli, workstationFrame(m, v)), 0u);
}
