// voxray-cli and the workstation read the same command line the same way: the input flags
// (input_flags.h) to the same load options, and the render values, a preset first, to the
// same parameters. The CLI's own option code is compiled in (app/cli).
#include <QCoreApplication>

#include <gtest/gtest.h>

#include "../io/test_support.h"
#include "input_options.h"
#include "render_flags.h"
#include "render_state_model.h"
#include "start_options.h"
#include "voxray/engine/input_flags.h"
#include "voxray/engine/quality.h"
#include "voxray/io/orientation.h"
#include "voxray/io/sample_volume.h"

using namespace voxray;

namespace {

struct CliRead {
  cli::InputOptions input;
  cli::RenderFlags render;
};

// voxray-cli render's options over ARGS (after the program name).
void readCli(CliRead& out, const std::vector<std::string>& args) {
  CLI::App app;
  out.input.add(app);
  out.render.add(app);
  std::vector<std::string> all = {"voxray-cli"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<const char*> argv;
  for (const auto& a : all) argv.push_back(a.c_str());
  app.parse(int(argv.size()), argv.data());
}

ui::StartOptions readGui(const std::vector<std::string>& args) {
  QStringList all = {"voxray"};
  for (const auto& a : args) all << QString::fromStdString(a);
  return ui::parseStartOptions(all);
}

std::string describe(const LoadOptions& o) {
  std::string out;
  for (const InputFlagSpec& spec : inputFlagSpecs()) out += spec.key + "=" + spec.format(o) + "\n";
  return out;
}

class CommandLine : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    static int argc = 1;
    static char name[] = "voxray_ui_command_line_tests";
    static char* argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv);  // QCommandLineParser reads its name
  }
};

TEST_F(CommandLine, CliAndGuiReadTheSameRawLayout) {
  const std::vector<std::string> args = {
      "slices",  "--raw-dims",    "256,256,113", "--raw-type",   "u16", "--raw-endian",
      "big",     "--raw-spacing", "0.5,0.5,2",   "--raw-offset", "64",  "--raw-rescale",
      "2,-1024", "--raw-range",   "3-115",       "--raw-axes",   "LPI", "--series",
      "7"};
  CliRead cli;
  readCli(cli, args);
  LoadOptions fromCli = cli.input.loadOptions();
  ui::StartOptions gui = readGui(args);
  EXPECT_EQ(cli.input.input, "slices");
  EXPECT_EQ(gui.input, "slices");
  EXPECT_EQ(describe(gui.load), describe(fromCli));
  ASSERT_TRUE(fromCli.raw && gui.load.raw);
  for (const LoadOptions* o : {&fromCli, &gui.load}) {
    EXPECT_EQ(o->raw->dims, glm::ivec3(256, 256, 113));
    EXPECT_EQ(o->raw->type, SampleType::U16);
    EXPECT_EQ(o->raw->order, ByteOrder::Big);
    EXPECT_EQ(o->raw->spacingMm, glm::dvec3(0.5, 0.5, 2.0));
    EXPECT_EQ(o->raw->headerBytes, 64u);
    EXPECT_EQ(o->raw->slope, 2.0);
    EXPECT_EQ(o->raw->intercept, -1024.0);
    EXPECT_EQ(o->raw->range, std::make_pair(3, 115));
    EXPECT_EQ(o->raw->direction, directionFromAxesCode("LPI"));
    EXPECT_EQ(o->series, "7");
  }
}

TEST_F(CommandLine, CliAndGuiRefuseTheSameWay) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--raw-spacing", "1,1,2"},
        std::vector<std::string>{"--raw-dims", "256,0"},
        std::vector<std::string>{"--raw-dims", "2,2", "--raw-range", "7"}}) {
    std::string cliError = test::errorMessage([&] {
      CliRead cli;
      readCli(cli, args);
      cli.input.loadOptions();
    });
    EXPECT_FALSE(cliError.empty()) << args[0];
    EXPECT_EQ(test::errorMessage([&] { readGui(args); }), cliError);
  }
}

TEST_F(CommandLine, CliAndGuiApplyAPresetFirstThenTheFlags) {
  const std::vector<std::string> args = {"--preset", "CT-Bone",     "--mode", "mip",    "--window",
                                         "1800,400", "--shininess", "600",    "--step", "0.5"};
  CliRead cli;
  readCli(cli, args);
  RenderParams fromCli = cli.render.params();
  RenderStateModel model;
  model.applyValues(readGui(args).renderValues);
  // The defaults that differ: the workstation's first start has its own look
  // (firstStartLook: Zucker-Hummel, jitter; issue 41 item 6); the CLI keeps the engine's.
  // A flag sets both alike.
  EXPECT_EQ(model.params().gradient, Gradient::ZuckerHummel);
  EXPECT_EQ(fromCli.gradient, RenderParams{}.gradient);
  EXPECT_TRUE(model.params().jitter);
  EXPECT_EQ(fromCli.jitter, RenderParams{}.jitter);
  fromCli.gradient = model.params().gradient;
  fromCli.jitter = model.params().jitter;
  EXPECT_EQ(toText(model.params()), toText(fromCli));
  RenderStateModel central;
  central.applyValues(readGui({"--gradient", "central"}).renderValues);
  EXPECT_EQ(central.params().gradient, Gradient::Central);
  EXPECT_EQ(fromCli.mode, Mode::Mip);  // the flag wins over CT-Bone's dvr
  EXPECT_EQ(fromCli.preset, "CT-Bone");
  EXPECT_EQ(fromCli.light.shininess, 600.0);
  EXPECT_EQ(model.quality().preset, "");  // an explicit step wins over the quality preset
}

}  // namespace

// Without a file the workstation opens the embedded sample CT (a real scan); --phantom
// opens the synthetic phantom, and only without a file.
TEST_F(CommandLine, NoInputOpensTheSampleCtAndPhantomOnRequest) {
  EXPECT_EQ(readGui({}).input, kSampleCtInput);
  EXPECT_EQ(readGui({"--size", "320x240"}).input, kSampleCtInput);
  EXPECT_EQ(readGui({"--phantom"}).input, "");
  EXPECT_EQ(readGui({"head.dcm"}).input, "head.dcm");
  try {
    readGui({"--phantom", "head.dcm"});
    ADD_FAILURE() << "--phantom with a file must be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("without an INPUT"), std::string::npos);
  }
}

// Issue 37: the study browser opens at start only without a file, with studies, and never
// for the smoke tests' screenshots.
TEST_F(CommandLine, StudyBrowserOpensAtStartOnlyWithoutAFileAndWithStudies) {
  EXPECT_TRUE(ui::opensStudyBrowserAtStart(readGui({}), true));
  EXPECT_FALSE(ui::opensStudyBrowserAtStart(readGui({}), false));
  EXPECT_FALSE(ui::opensStudyBrowserAtStart(readGui({"head.dcm"}), true));
  EXPECT_FALSE(ui::opensStudyBrowserAtStart(readGui({"--phantom"}), true));
  EXPECT_FALSE(ui::opensStudyBrowserAtStart(readGui({"--screenshot", "x.png"}), true));
  EXPECT_FALSE(ui::opensStudyBrowserAtStart(readGui({"--quit-after-first-frame"}), true));
}
