// Exports never replace a file without a yes, asked with the name that will be written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "export_target.h"

using namespace voxray;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("voxray_ui_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(ExportTarget, AddsPngWhenThereIsNoSuffix) {
  EXPECT_EQ(withImageSuffix("/tmp/shot"), "/tmp/shot.png");
  EXPECT_EQ(withImageSuffix("/tmp/shot.tif"), "/tmp/shot.tif");
  EXPECT_EQ(withImageSuffix("/tmp/a.b/shot"), "/tmp/a.b/shot.png");
  EXPECT_EQ(withImageSuffix(""), "");
}

TEST(ExportTarget, NewFileIsWrittenWithoutAsking) {
  fs::path d = freshDir("export_new");
  int asked = 0;
  auto target = resolveExportTarget((d / "shot.png").string(), [&](const std::string&) {
    ++asked;
    return false;
  });
  ASSERT_TRUE(target.has_value());
  EXPECT_EQ(*target, (d / "shot.png").string());
  EXPECT_EQ(asked, 0);
}

TEST(ExportTarget, ExistingFileNeedsAYes) {
  fs::path d = freshDir("export_existing");
  std::ofstream(d / "shot.png") << "keep me";
  std::vector<std::string> asked;
  auto no = resolveExportTarget((d / "shot.png").string(), [&](const std::string& p) {
    asked.push_back(p);
    return false;
  });
  EXPECT_FALSE(no.has_value());
  ASSERT_EQ(asked.size(), 1u);
  EXPECT_EQ(asked[0], (d / "shot.png").string());
  auto yes =
      resolveExportTarget((d / "shot.png").string(), [](const std::string&) { return true; });
  EXPECT_TRUE(yes.has_value());
  // No way to ask (no callback) means no.
  EXPECT_FALSE(resolveExportTarget((d / "shot.png").string(), {}).has_value());
}

TEST(ExportTarget, AsksAboutTheNameWithTheAddedSuffix) {
  // The user types "shot"; the file dialog sees no "shot" and would not ask, but
  // "shot.png" exists and is what would be replaced.
  fs::path d = freshDir("export_suffix");
  std::ofstream(d / "shot.png") << "keep me";
  std::string asked;
  auto target = resolveExportTarget((d / "shot").string(), [&](const std::string& p) {
    asked = p;
    return false;
  });
  EXPECT_FALSE(target.has_value());
  EXPECT_EQ(asked, (d / "shot.png").string());
}
