// voxray-cli db import|find|series|priors|verify|delete and the db:SERIES_UID input, through
// the executable's JSON output; the counts cross-checked with pydicom.

#include <filesystem>
#include <fstream>
#include <map>

#include <gmock/gmock.h>
#include <nlohmann/json.hpp>

#include "command_run.h"
#include "studydb_test_support.h"

namespace fs = std::filesystem;
using nlohmann::json;
using testing::HasSubstr;

namespace voxray::test {
namespace {

using CliRun = CommandResult;

// COMMAND through the shell within 120 s; stderr joined to stdout only when asked.
CliRun shell(const std::string& command, bool withStderr = false) {
  return runCommand("timeout 120 " + command + (withStderr ? " 2>&1" : ""));
}

CliRun cli(const std::string& args, bool withStderr = false) {
  return shell(std::string(VOXRAY_CLI) + " " + args, withStderr);
}

json parsed(const CliRun& r) {
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return json::parse(r.output);
}

TEST(StudyDbCli, ImportFindSeriesVerifyAndOpenASeriesByUid) {
  const std::string db = tempFolder("db");
  const std::string scans = dicomPath("ct-philips-phantom") + " " + dicomPath("ct-ge-tilt") + " " +
                            dicomPath("ct-visible-human-pelvis");
  json imported = parsed(cli("db import " + scans + " --db " + db + " --json"));
  EXPECT_EQ(imported.at("added"), 213);
  EXPECT_EQ(imported.at("skipped").size(), 6u);
  EXPECT_EQ(imported.at("studies").size(), 3u);
  EXPECT_EQ(imported.at("series").size(), 5u);
  // Text output and stderr never carry a patient's name (they are 'HEAD', 'REMOVED', 'Eve').
  CliRun text = cli("db import " + dicomPath("ct-visible-human-pelvis") + " --db " + db, true);
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("150 unchanged"));
  EXPECT_THAT(text.output, testing::Not(HasSubstr("Eve")));

  json all = parsed(cli("db find --db " + db + " --modality CT --json"));
  EXPECT_EQ(all.size(), 3u);
  json eve = parsed(cli("db find --db " + db + " --patient eve --json"));
  ASSERT_EQ(eve.size(), 1u);
  EXPECT_EQ(eve[0].at("patient_name"), "Eve");  // the user asked for the patient
  EXPECT_EQ(eve[0].at("images"), 150);
  EXPECT_EQ(
      parsed(cli("db find --db " + db + " --date 20150101-20151231 --json"))[0].at("study_uid"),
      kPhilipsStudy);
  EXPECT_EQ(parsed(cli("db find --db " + db + " --description trauma --json")).size(), 1u);
  EXPECT_EQ(parsed(cli("db find --db " + db + " --id PLASTIC --json")).size(), 1u);

  // Series counts against pydicom's reading of the same files.
  json series = parsed(cli("db series " + kPhilipsStudy + " --db " + db + " --json"));
  ASSERT_EQ(series.size(), 3u);
  const std::string python = VOXRAY_PYTHON;
  ASSERT_TRUE(fs::exists(python)) << python << " is missing: run scripts/bootstrap";
  CliRun counted = shell(python +
                         " -c \"import pydicom, os, collections, json; c = "
                         "collections.Counter(); [c.update([pydicom.dcmread(os.path.join(d, "
                         "f), stop_before_pixels=True).get('SeriesInstanceUID')]) for d, _, "
                         "fs in os.walk('" +
                         dicomPath("ct-philips-phantom") +
                         "') for f in fs if f.startswith('I')]; print(json.dumps(c))\"");
  json byPydicom = parsed(counted);
  for (const auto& s : series)
    EXPECT_EQ(s.at("images"), byPydicom.at(s.at("series_uid").get<std::string>()))
        << s.at("series_uid");

  // db:UID and --db/--series open the series as its folder does.
  json fromFolder = parsed(cli("info " + dicomPath("ct-ge-tilt") + " --json"));
  json fromDb = parsed(cli("info db:" + kTiltSeries + " --db " + db + " --json"));
  json fromFlags = parsed(cli("info --db " + db + " --series " + kTiltSeries + " --json"));
  for (const char* key : {"dims", "spacing_mm", "origin_mm", "hu_min", "hu_max"}) {
    EXPECT_EQ(fromDb.at(key), fromFolder.at(key)) << key;
    EXPECT_EQ(fromFlags.at(key), fromFolder.at(key)) << key;
  }
  CliRun unknown = cli("info db:1.2.3.4 --db " + db, true);
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_THAT(unknown.output, HasSubstr("Series 1.2.3.4 is not in the study database"));

  json verified = parsed(cli("db verify --db " + db + " --rebuild --json"));
  EXPECT_EQ(verified.at("checked"), 213);
  EXPECT_EQ(verified.at("ok"), 213);
  EXPECT_EQ(verified.at("studies"), 3);
  EXPECT_TRUE(verified.at("rebuilt").get<bool>());

  // A damaged database file: made again from the journal, and the user is told.
  {
    std::fstream f(db + "/studies.sqlite", std::ios::in | std::ios::out | std::ios::binary);
    f.write("garbage, not SQLite", 19);
  }
  CliRun damaged = cli("db find --db " + db + " --modality CT", true);
  EXPECT_EQ(damaged.exitCode, 0) << damaged.output;
  EXPECT_THAT(damaged.output, HasSubstr("was damaged: rebuilt from its journal"));
  EXPECT_THAT(damaged.output, HasSubstr(kPhilipsStudy));
  EXPECT_EQ(parsed(cli("db find --db " + db + " --json")).size(), 3u);

  json deleted = parsed(cli("db delete " + kPhilipsStudy + " --db " + db + " --json"));
  EXPECT_EQ(deleted.at("instances"), 35);
  EXPECT_EQ(parsed(cli("db find --db " + db + " --json")).size(), 2u);
  EXPECT_TRUE(fs::exists(dicomPath("ct-philips-phantom/S2010/I10")));
  CliRun again = cli("db delete " + kPhilipsStudy + " --db " + db, true);
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_THAT(again.output, HasSubstr("is not in the study database"));
}

// db import --pacs-cache: every cached series, copied into the database's store (the cache
// evicts its series; the database keeps its copies).
TEST(StudyDbCli, PacsCacheSeriesAreCopiedIntoTheStore) {
  const std::string cache = tempFolder("cache"), db = tempFolder("db");
  const std::string series = cache + "/series/" + kTiltSeries;
  fs::create_directories(series);
  for (const auto& f : fs::directory_iterator(dicomPath("ct-ge-tilt")))
    if (f.path().extension() == ".dcm")
      fs::copy_file(f.path(), series + "/" + f.path().filename().string());
  json index = {{"series",
                 {{{"studyUid", "1.2.826.0.1.3680043.9.4245.1760717064491086528325869788156915668"},
                   {"seriesUid", kTiltSeries},
                   {"folder", series},
                   {"bytes", 0},
                   {"lastUsed", 0},
                   {"images", 28}}}}};
  std::ofstream(cache + "/index.json") << index.dump();
  json imported =
      parsed(cli("db import --pacs-cache --cache " + cache + " --db " + db + " --json"));
  EXPECT_EQ(imported.at("added"), 28);
  fs::remove_all(cache);
  json verified = parsed(cli("db verify --db " + db + " --json"));
  EXPECT_EQ(verified.at("ok"), 28);
  int stored = 0;
  for (const auto& f : fs::recursive_directory_iterator(db + "/store"))
    stored += f.is_regular_file() ? 1 : 0;
  EXPECT_EQ(stored, 28);
}

TEST(StudyDbCli, TheDefaultDatabaseIsInTheUsersDataFolder) {
  const std::string data = tempFolder("xdg");
  CliRun r = shell("env -u VOXRAY_STUDY_DB XDG_DATA_HOME=" + data + " " + VOXRAY_CLI +
                   " db import " + dicomPath("ct-ge-tilt") + " --json");
  EXPECT_EQ(parsed(r).at("database"), data + "/voxray/studies");
  EXPECT_TRUE(fs::exists(data + "/voxray/studies/studies.sqlite"));
  EXPECT_TRUE(fs::exists(data + "/voxray/studies/imports.jsonl"));
}

}  // namespace
}  // namespace voxray::test
