// The inputs that once crashed, aborted or hung voxray-cli (issue 19), run through the real
// executable: each must end with exit code 0 or 1 and a message, never a signal, an abort
// (134) or the time-out (124).
#include <gmock/gmock.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "command_run.h"
#include "dicom_writer.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using voxray::test::CommandResult;

CommandResult cli(const std::string& args) {
  return voxray::test::runCommand("VOXRAY_DEVICE=cpu timeout 60 " + std::string(VOXRAY_CLI) + " " +
                                  args + " 2>&1");
}

class CliHostile : public voxray::test::ScratchFolderTest {
 protected:
  CliHostile() : ScratchFolderTest("voxray-cli-hostile-") {}

  // Three slices 1 mm apart: a volume.
  std::string series(voxray::test::TestSlice s) {
    fs::create_directories(dir_ / "series");
    for (int k = 0; k < 3; ++k) {
      s.instance = k + 1;
      s.z = k;
      voxray::test::writeTestSlice(path("series/" + std::to_string(k + 1) + ".dcm"), s);
    }
    return path("series");
  }
};

TEST_F(CliHostile, InfoJsonOfALatin1SeriesIsUtf8) {
  voxray::test::TestSlice s;
  s.charset = "ISO_IR 100";
  s.description =
      "Kn\xF6"
      "chel";
  s.patientName =
      "M\xFC"
      "ller^J\xFC"
      "rgen";
  CommandResult r = cli("info --json " + series(s));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);  // throws on bytes that are not UTF-8
  EXPECT_EQ(j["series"][0]["description"], "Knöchel");
  EXPECT_EQ(r.output.find("ller"), std::string::npos) << "patient name in info output";
}

TEST_F(CliHostile, InfoJsonOfBytesThatAreNotUtf8ShowsReplacementCharacters) {
  voxray::test::TestSlice s;
  s.charset = "ISO_IR 192";
  s.description = "Kopf \xFF";
  CommandResult r = cli("info --json " + series(s));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output)["series"][0]["description"], "Kopf \xEF\xBF\xBD");
}

// Text output escapes control characters from files (a screen clear, a title change, a CR LF
// that fakes a line, a NUL); --json keeps them as JSON escapes (issue 39).
TEST_F(CliHostile, InfoTextEscapesControlCharactersFromTheFile) {
  voxray::test::TestSlice s;
  s.charset = "ISO_IR 192";
  s.description = std::string("\x1b]0;pwned\x07\x1b[2J\r\nFAKE\0end", 24);
  CommandResult r = cli("info " + series(s));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (char c : {'\x1b', '\a', '\r', '\0'})
    EXPECT_EQ(r.output.find(c), std::string::npos) << r.output;
  EXPECT_THAT(r.output, HasSubstr("\\x1b]0;pwned\\x07\\x1b[2J\\r\\nFAKE"));
}

TEST_F(CliHostile, SequencesNested100000DeepAreAnError) {
  const std::string file = path("nested.dcm");
  voxray::test::writeTestSlice(file, {});
  voxray::test::nestSequences(file, 100000);
  for (const std::string& command : {std::string("info"), "render -o " + path("never.png")}) {
    CommandResult r = cli(command + " " + file);
    EXPECT_EQ(r.exitCode, 1) << command << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("nested deeper than Voxray reads")) << command;
  }
  EXPECT_FALSE(fs::exists(path("never.png")));
}

TEST_F(CliHostile, FuzzerRegressionsEndInAMessage) {
  for (const auto& entry : fs::directory_iterator(VOXRAY_FUZZ_REGRESSIONS)) {
    if (entry.path().extension() == ".md") continue;
    for (const char* command : {"info --json", "info"}) {
      CommandResult r = cli(std::string(command) + " " + entry.path().string());
      EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 1) << entry.path() << ": " << r.output;
      EXPECT_THAT(r.output, testing::Not(HasSubstr("terminate called")));
    }
  }
}

TEST_F(CliHostile, HugeRawRangeEndsAtTheFirstGap) {
  for (int n = 1; n <= 3; ++n) {
    std::FILE* f = std::fopen(path("s." + std::to_string(n)).c_str(), "wb");
    std::fwrite("\0\0\0\0\0\0\0\0", 1, 8, f);
    std::fclose(f);
  }
  CommandResult r = cli("info " + path("s.%d") + " --raw-dims 2,2 --raw-range 1-2000000000");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("slices 4-1004 missing after s.3"));
}

TEST_F(CliHostile, FifoIsRefusedNotWaitedOn) {
  ASSERT_EQ(mkfifo(path("pipe").c_str(), 0600), 0);
  for (const std::string& flags : {std::string(), std::string(" --raw-dims 2,2")}) {
    CommandResult r = cli("info " + path("pipe") + flags);
    EXPECT_EQ(r.exitCode, 1) << flags << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("is a FIFO (named pipe), not a regular file or folder"));
  }
}

}  // namespace
