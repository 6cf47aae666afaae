// A DICOMDIR names files relative to its folder (issue 39): an absolute ReferencedFileID, one
// with an empty first component or "..", or a link (to a file or a folder) inside the folder
// must not load a file from elsewhere. The study here: three slices (z 0, 1, 2 mm) beside the
// DICOMDIR, and a fourth slice of the same series (z 3 mm) outside its folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "../io/test_support.h"
#include "dicom_writer.h"
#include "test_data.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;

struct Study {
  test::TempDir dir;
  fs::path study = dir.path() / "study", outside = dir.path() / "outside";
  Study() {
    fs::create_directories(study / "IMG");
    fs::create_directories(outside);
    for (int k = 0; k < 4; ++k) {
      test::TestSlice s;
      s.z = k;
      s.instance = k + 1;
      test::writeTestSlice(
          k < 3 ? (study / "IMG" / std::to_string(k + 1)).string() : (outside / "4").string(), s);
    }
  }
  // The volume the DICOMDIR opens when it lists the three slices and then HOSTILE.
  Volume openWith(const std::string& hostile) {
    test::writeDicomDir((study / "DICOMDIR").string(), {"IMG\\1", "IMG\\2", "IMG\\3", hostile});
    return importDicom((study / "DICOMDIR").string());
  }
};

// "\tmp\...\outside\4": the backslash path starts with an empty component (an absolute path).
std::string backslashed(const fs::path& p) {
  std::string s = p.string();
  std::replace(s.begin(), s.end(), '/', '\\');
  return s;
}

void expectOnlyTheStudy(const Volume& v) {
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 3));
  EXPECT_TRUE(test::anyContains(v.warnings, "the DICOMDIR names 1 file(s) outside its folder"));
}

TEST(DicomDirEscape, AnAbsoluteReferencedFileIdIsNotRead) {
  Study s;
  expectOnlyTheStudy(s.openWith(backslashed(s.outside / "4")));
}

TEST(DicomDirEscape, ADotDotReferencedFileIdIsNotRead) {
  Study s;
  expectOnlyTheStudy(s.openWith("..\\outside\\4"));
}

TEST(DicomDirEscape, LinksToFilesAndFoldersOutsideAreNotFollowed) {
  Study s;
  fs::create_symlink(s.outside / "4", s.study / "LINK");
  expectOnlyTheStudy(s.openWith("LINK"));
  fs::create_directory_symlink(s.outside, s.study / "SUB");
  expectOnlyTheStudy(s.openWith("SUB\\4"));
}

// Entries that are gone: the folder is searched instead, and a link there that leads out is
// passed over too.
TEST(DicomDirEscape, TheFolderSearchedForMissingEntriesKeepsToIt) {
  Study s;
  fs::create_symlink(s.outside / "4", s.study / "LINK");
  test::writeDicomDir((s.study / "DICOMDIR").string(), {"GONE"});
  const Volume v = importDicom((s.study / "DICOMDIR").string());
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 3));
  EXPECT_TRUE(test::anyContains(v.warnings, "the DICOMDIR lists 1 file(s) that do not exist"));
}

// A link inside the folder to a file inside it is followed as before.
TEST(DicomDirEscape, LinksWithinTheFolderStillOpen) {
  Study s;
  fs::create_symlink(s.study / "IMG" / "3", s.study / "THREE");
  test::writeDicomDir((s.study / "DICOMDIR").string(), {"IMG\\1", "IMG\\2", "THREE"});
  const Volume v = importDicom((s.study / "DICOMDIR").string());
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 3));
  EXPECT_FALSE(test::anyContains(v.warnings, "DICOMDIR"));
}

}  // namespace
}  // namespace voxray
