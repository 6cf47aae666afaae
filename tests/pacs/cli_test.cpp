// voxray-cli pacs echo|find|get|send against a real Orthanc, through its JSON output.
#include <sys/wait.h>

#include <cstdio>

#include <gmock/gmock.h>
#include <nlohmann/json.hpp>

#include "pacs_test_support.h"

namespace voxray::test {
namespace {

struct CliRun {
  int status = 0;
  std::string out;
};

// Runs voxray-cli with ARGS (stderr joined to stdout only when asked).
CliRun cli(const std::string& args, bool withStderr = false) {
  std::string command = std::string(VOXRAY_CLI) + " " + args + (withStderr ? " 2>&1" : "");
  CliRun r;
  FILE* p = popen(command.c_str(), "r");
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  r.status = WEXITSTATUS(pclose(p));
  return r;
}

using PacsCliTest = PacsTest;

std::string address(const PacsNode& node) { return "dicom://" + node.label(); }

TEST_F(PacsCliTest, EchoFindAndGetThroughTheCommandLine) {
  std::string node = address(server().dimseNode());
  CliRun echo = cli("pacs echo " + node + " --json");
  ASSERT_EQ(echo.status, 0) << echo.out;
  EXPECT_TRUE(nlohmann::json::parse(echo.out).at("ok").get<bool>());

  CliRun find = cli("pacs find " + node + " --name HEAD --json");
  ASSERT_EQ(find.status, 0) << find.out;
  auto studies = nlohmann::json::parse(find.out);
  ASSERT_EQ(studies.size(), 1u);
  EXPECT_EQ(studies[0].at("study_uid"), kPhantomStudy);
  EXPECT_FALSE(studies[0].contains("patient_name"));                    // only with --show-patient
  EXPECT_THAT(find.out, testing::Not(testing::HasSubstr("\"HEAD\"")));  // the patient name

  std::string cache = tempFolder("cli-cache");
  CliRun get = cli("pacs get " + node + " --study " + kPhantomStudy + " --series " +
                   kPhantomSeries + " --cache " + cache + " --json");
  ASSERT_EQ(get.status, 0) << get.out;
  auto info = nlohmann::json::parse(get.out);
  EXPECT_EQ(info.at("images"), 28);
  Volume disk = loadVolume(dicomPath("ct-philips-phantom/S2010"));
  EXPECT_EQ(info.at("dims"), nlohmann::json({disk.dims.x, disk.dims.y, disk.dims.z}));
  EXPECT_EQ(info.at("cache_folder").get<std::string>().rfind(cache, 0), 0u);
}

TEST_F(PacsCliTest, WrongAeExitsWithOneAndAMessage) {
  PacsNode node = server().dimseNode();
  node.calledAe = "WRONG";
  CliRun echo = cli("pacs echo " + address(node), true);
  EXPECT_EQ(echo.status, 1);
  EXPECT_THAT(echo.out, testing::HasSubstr("refused Voxray"));
}

}  // namespace
}  // namespace voxray::test
