// voxray-cli pacs echo|find|get|send against a real Orthanc, through its JSON output.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <nlohmann/json.hpp>

#include "canned_http_server.h"
#include "command_run.h"
#include "pacs_test_support.h"

namespace voxray::test {
namespace {

using CliRun = CommandResult;

// Runs voxray-cli with ARGS (stderr joined to stdout only when asked), within 60 s and 4 GB
// of address space: a command that blocks or reads without end fails rather than hangs.
CliRun cli(const std::string& args, bool withStderr = false) {
  return runCommand("ulimit -v 4000000; timeout 60 " + std::string(VOXRAY_CLI) + " " + args +
                    (withStderr ? " 2>&1" : ""));
}

using PacsCliTest = PacsTest;

std::string address(const PacsNode& node) { return "dicom://" + node.label(); }

TEST_F(PacsCliTest, EchoFindAndGetThroughTheCommandLine) {
  std::string node = address(server().dimseNode());
  CliRun echo = cli("pacs echo " + node + " --json");
  ASSERT_EQ(echo.exitCode, 0) << echo.output;
  EXPECT_TRUE(nlohmann::json::parse(echo.output).at("ok").get<bool>());

  CliRun find = cli("pacs find " + node + " --name HEAD --json");
  ASSERT_EQ(find.exitCode, 0) << find.output;
  auto studies = nlohmann::json::parse(find.output);
  ASSERT_EQ(studies.size(), 1u);
  EXPECT_EQ(studies[0].at("study_uid"), kPhantomStudy);
  EXPECT_FALSE(studies[0].contains("patient_name"));  // only with --show-patient
  EXPECT_THAT(find.output, testing::Not(testing::HasSubstr("\"HEAD\"")));  // the patient name

  std::string cache = tempFolder("cli-cache");
  CliRun get = cli("pacs get " + node + " --study " + kPhantomStudy + " --series " +
                   kPhantomSeries + " --cache " + cache + " --json");
  ASSERT_EQ(get.exitCode, 0) << get.output;
  auto info = nlohmann::json::parse(get.output);
  EXPECT_EQ(info.at("images"), 28);
  Volume disk = loadVolume(dicomPath("ct-philips-phantom/S2010"));
  EXPECT_EQ(info.at("dims"), nlohmann::json({disk.dims.x, disk.dims.y, disk.dims.z}));
  EXPECT_EQ(info.at("cache_folder").get<std::string>().rfind(cache, 0), 0u);
}

// Issue 39 item 8: over DICOMweb, pacs get decodes the images as they arrive (not from the
// cache's files afterwards) and reports the volume the same files give from disk; --no-open
// only fills the cache, which then opens as the same volume.
TEST_F(PacsCliTest, WebGetOpensTheVolumeAsFromDiskAndNoOpenOnlyCaches) {
  const PacsNode web = server().webNode();
  const std::string config = tempFolder("cli-config");
  std::filesystem::create_directories(config + "/voxray");
  std::ofstream(config + "/voxray/pacs-nodes.json") << nlohmann::json{
      {"nodes",
       {{"orthanc-web",
         {{"url", web.baseUrl},
          {"user", web.user},
          {"password", web.password}}}}}}.dump();
  const std::string get = "env XDG_CONFIG_HOME=" + config + " " + std::string(VOXRAY_CLI) +
                          " pacs get orthanc-web --study " + kPhantomStudy + " --series " +
                          kPhantomSeries + " --json --cache ";
  CliRun whole = runCommand("timeout 60 " + get + tempFolder("web-cache"));
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  const auto info = nlohmann::json::parse(whole.output);
  const Volume disk = loadVolume(dicomPath("ct-philips-phantom/S2010"));
  EXPECT_EQ(info.at("images"), 28);
  EXPECT_EQ(info.at("dims"), nlohmann::json({disk.dims.x, disk.dims.y, disk.dims.z}));
  for (int a = 0; a < 3; ++a) {  // the same header values, through JSON's doubles
    EXPECT_NEAR(info.at("spacing_mm")[a].get<double>(), disk.spacingMm[a], 1e-9);
    EXPECT_NEAR(info.at("origin_mm")[a].get<double>(), disk.originMm[a], 1e-9);
  }
  // The HU range (the output computes it from the decoded voxels), as from disk.
  EXPECT_EQ(info.at("hu_min").get<double>(), disk.toPhysical(storedRange(disk).min));
  EXPECT_EQ(info.at("hu_max").get<double>(), disk.toPhysical(storedRange(disk).max));
  EXPECT_TRUE(info.contains("ready_s"));

  CliRun cached = runCommand("timeout 60 " + get + tempFolder("web-cache") + " --no-open");
  ASSERT_EQ(cached.exitCode, 0) << cached.output;
  const auto only = nlohmann::json::parse(cached.output);
  EXPECT_EQ(only.at("images"), 28);
  EXPECT_FALSE(only.contains("dims"));  // nothing was decoded
  EXPECT_FALSE(only.contains("ready_s"));
  const std::string folder = only.at("cache_folder").get<std::string>();
  int files = 0;
  for (const auto& f : std::filesystem::directory_iterator(folder)) files += f.is_regular_file();
  EXPECT_EQ(files, 28);
  CliRun opened = cli("info " + folder + " --json");
  ASSERT_EQ(opened.exitCode, 0) << opened.output;
  const auto again = nlohmann::json::parse(opened.output);
  EXPECT_EQ(again.at("dims"), info.at("dims"));
  EXPECT_EQ(again.at("hu_min"), info.at("hu_min"));
  EXPECT_EQ(again.at("hu_max"), info.at("hu_max"));
}

// pacs get --db: the retrieval is copied into the study database (issue 37), found there
// next time and opened from it as the same volume.
TEST_F(PacsCliTest, GetWithDbStoresTheSeriesInTheStudyDatabase) {
  std::string node = address(server().dimseNode());
  std::string cache = tempFolder("db-cache"), db = tempFolder("db");
  CliRun get = cli("pacs get " + node + " --study " + kPhantomStudy + " --series " +
                   kPhantomSeries + " --cache " + cache + " --db " + db + " --json");
  ASSERT_EQ(get.exitCode, 0) << get.output;
  auto info = nlohmann::json::parse(get.output);
  EXPECT_EQ(info.at("study_db_instances"), 28);
  CliRun series = cli("db series " + std::string(kPhantomStudy) + " --db " + db + " --json");
  ASSERT_EQ(series.exitCode, 0) << series.output;
  auto list = nlohmann::json::parse(series.output);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].at("series_uid"), kPhantomSeries);
  EXPECT_EQ(list[0].at("images"), 28);
  // Copies the database owns: the cache may evict its own.
  std::filesystem::remove_all(cache);
  CliRun opened = cli("info db:" + std::string(kPhantomSeries) + " --db " + db + " --json");
  ASSERT_EQ(opened.exitCode, 0) << opened.output;
  EXPECT_EQ(nlohmann::json::parse(opened.output).at("dims"), info.at("dims"));
}

TEST_F(PacsCliTest, WrongAeExitsWithOneAndAMessage) {
  PacsNode node = server().dimseNode();
  node.calledAe = "WRONG";
  CliRun echo = cli("pacs echo " + address(node), true);
  EXPECT_EQ(echo.exitCode, 1);
  EXPECT_THAT(echo.output, testing::HasSubstr("refused Voxray"));
}

// At the series level each match is a series: its number, not a count of series (which was
// 0 for every match).
TEST_F(PacsCliTest, SeriesLevelFindPrintsSeriesNotASeriesCount) {
  std::string node = address(server().dimseNode());
  std::string args = "pacs find " + node + " --level series --study " + kPhantomStudy;
  CliRun find = cli(args + " --json");
  ASSERT_EQ(find.exitCode, 0) << find.output;
  auto series = nlohmann::json::parse(find.output);
  ASSERT_EQ(series.size(), 3u);
  for (const auto& s : series) {
    EXPECT_FALSE(s.contains("series")) << s.dump();
    EXPECT_TRUE(s.at("series_number").is_number_integer()) << s.dump();
    if (s.at("series_uid") == kPhantomSeries) {
      EXPECT_EQ(s.at("images"), 28);
    }
  }
  CliRun text = cli(args);
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_THAT(text.output, testing::Not(testing::HasSubstr(" series ")));
  EXPECT_THAT(text.output, testing::HasSubstr("  28 images  " + std::string(kPhantomSeries)));
}

// pacs send takes only regular files that are DICOM: /dev/zero (read without end), a FIFO
// (blocks), a folder and a text file are refused by name, nothing sent.
TEST_F(PacsCliTest, SendRefusesWhatIsNotARegularDicomFile) {
  auto instances = [&] {
    return nlohmann::json::parse(server().get("/statistics")).at("CountInstances").get<int>();
  };
  const int before = instances();
  std::string dir = tempFolder("send");
  std::string fifo = dir + "/fifo", text = dir + "/shadow";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::ofstream(text) << "root:$6$salt$hash:19000:0:99999:7:::\n";
  for (const std::string& node : {address(server().dimseNode()), server().webNode().baseUrl}) {
    for (const auto& [file, says] :
         std::vector<std::pair<std::string, std::string>>{{"/dev/zero", "not a regular file"},
                                                          {fifo, "not a regular file"},
                                                          {dir, "not a regular file"},
                                                          {text, "not a DICOM file"}}) {
      CliRun send = cli("pacs send " + node + " " + file, true);
      EXPECT_EQ(send.exitCode, 1) << file << ": " << send.output;
      EXPECT_THAT(send.output, testing::AllOf(testing::HasSubstr(file), testing::HasSubstr(says)))
          << node;
    }
  }
  EXPECT_EQ(instances(), before);
}

// Text output escapes control characters from the server (a screen clear, a title change,
// a CR LF that fakes a line); --json has them as JSON escapes.
TEST(PacsCliTextTest, FindEscapesControlCharactersFromTheServer) {
  const std::string body =
      R"([{"0020000D":{"vr":"UI","Value":["1.2.3"]},"00080020":{"vr":"DA","Value":["20200101"]},)"
      R"("00081030":{"vr":"LO","Value":["\u001b]0;pwned\u0007\u001b[2J\r\nFAKE"]}}])";
  CannedHttpServer server(CannedHttpServer::answer("200 OK", "application/dicom+json", body));
  CliRun find = cli("pacs find " + server.address());
  ASSERT_EQ(find.exitCode, 0) << find.output;
  for (char c : {'\x1b', '\a', '\r'})
    EXPECT_EQ(find.output.find(c), std::string::npos) << find.output;
  EXPECT_THAT(find.output, testing::HasSubstr("\\x1b]0;pwned\\x07\\x1b[2J\\r\\nFAKE\n"));
}

// An error message that quotes the server (here its content type) is escaped too.
TEST(PacsCliTextTest, ErrorMessagesEscapeControlCharactersFromTheServer) {
  CannedHttpServer server(
      CannedHttpServer::answer("200 OK", "text/html\x1b]0;pwned\x07", "<html></html>"));
  std::string cache = tempFolder("cache");
  CliRun get =
      cli("pacs get " + server.address() + " --study 1.2 --series 1.2.3 --cache " + cache, true);
  EXPECT_EQ(get.exitCode, 1) << get.output;
  for (char c : {'\x1b', '\a'}) EXPECT_EQ(get.output.find(c), std::string::npos) << get.output;
  EXPECT_THAT(get.output, testing::HasSubstr("text/html\\x1b]0;pwned\\x07"));
}

// Without --show-patient, a failed search names neither the patient nor the node's token
// (its URL's query values are hidden).
TEST(PacsCliTextTest, FailedSearchPrintsNoPatientDataAndNoToken) {
  CannedHttpServer server("HTTP/1.1 500 Internal Server Error\r\nContent-Length: 0\r\n\r\n");
  CliRun find = cli("pacs find '" + server.address() +
                        "?access_token=SECRET-TOKEN' --name 'DOE^JOHN' --id PID-4711",
                    true);
  EXPECT_EQ(find.exitCode, 1) << find.output;
  EXPECT_THAT(find.output, testing::AllOf(testing::HasSubstr("HTTP 500"),
                                          testing::Not(testing::HasSubstr("DOE")),
                                          testing::Not(testing::HasSubstr("PID-4711")),
                                          testing::Not(testing::HasSubstr("SECRET-TOKEN"))));
}

// Counts that are no whole number (1.5e300, 2.5) are unknown ("?", null), not 0.
TEST(PacsCliTextTest, CountsThatAreNoWholeNumberPrintAsUnknown) {
  const std::string body =
      R"([{"0020000D":{"vr":"UI","Value":["1.2.3"]},"00201206":{"vr":"IS","Value":[1.5e300]},)"
      R"("00201208":{"vr":"IS","Value":[2.5]}}])";
  {
    CannedHttpServer server(CannedHttpServer::answer("200 OK", "application/dicom+json", body));
    CliRun find = cli("pacs find " + server.address());
    ASSERT_EQ(find.exitCode, 0) << find.output;
    EXPECT_THAT(find.output, testing::HasSubstr("? series  ? images  1.2.3"));
  }
  CannedHttpServer server(CannedHttpServer::answer("200 OK", "application/dicom+json", body));
  CliRun find = cli("pacs find " + server.address() + " --json");
  ASSERT_EQ(find.exitCode, 0) << find.output;
  auto match = nlohmann::json::parse(find.output).at(0);
  EXPECT_TRUE(match.at("series").is_null()) << find.output;
  EXPECT_TRUE(match.at("images").is_null()) << find.output;
}

}  // namespace
}  // namespace voxray::test
