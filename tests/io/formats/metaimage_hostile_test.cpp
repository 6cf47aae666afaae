// A MetaImage header's ElementDataFile is held to the NRRD rule (issue 39): a data file outside
// the header's folder, or a link that leads out of it, is not read as voxels. The files are
// written into a temporary folder the test makes.
#include <filesystem>

#include "format_test_support.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::HasSubstr;

// A 4 x 3 x 2 MET_SHORT image whose ElementDataFile is DATA_FILE (and any lines after it).
std::string hostileMetaImageHeader(const std::string& dataFile) {
  return "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\nElementType = MET_SHORT\n"
         "ElementDataFile = " +
         dataFile + "\n";
}

TEST(FormatsMetaImageHostile, DataFilesOutsideTheHeadersFolderAreRefused) {
  TempDir dir;
  test::writeBytes(dir.file("outside.raw"), std::vector<uint8_t>(48, 7));
  test::writeBytes(dir.file("outside1.raw"), std::vector<uint8_t>(24, 7));
  test::writeBytes(dir.file("outside2.raw"), std::vector<uint8_t>(24, 7));
  fs::create_directories(dir.path() / "study");
  fs::create_symlink(dir.file("outside.raw"), dir.path() / "study" / "link.raw");
  const std::string path = (dir.path() / "study" / "v.mhd").string();
  for (const std::string& name : {std::string("/etc/passwd"), std::string("../outside.raw"),
                                  dir.file("outside.raw"), std::string("link.raw")}) {
    SCOPED_TRACE(name);
    test::writeHeaderFile(path, hostileMetaImageHeader(name));
    EXPECT_THAT(
        test::errorMessage([&] { loadVolume(path); }),
        HasSubstr(path + ": its data file '" + name + "' lies outside the header's folder"));
  }
  test::writeHeaderFile(path, hostileMetaImageHeader("LIST 2D\n../outside1.raw\n../outside2.raw"));
  EXPECT_THAT(test::errorMessage([&] { loadVolume(path); }),
              HasSubstr("its data file '../outside1.raw' lies outside the header's folder"));
  test::writeHeaderFile(path, hostileMetaImageHeader("../outside%d.raw 1 2 1"));
  EXPECT_THAT(test::errorMessage([&] { loadVolume(path); }),
              HasSubstr("its data file '../outside1.raw' lies outside the header's folder"));
  // The same data beside the header opens.
  fs::copy_file(dir.file("outside.raw"), dir.path() / "study" / "inside.raw");
  test::writeHeaderFile(path, hostileMetaImageHeader("inside.raw"));
  EXPECT_EQ(loadVolume(path).dims, glm::ivec3(4, 3, 2));
}

// A header that claims more samples than its file or data file can hold is refused before the
// samples' buffer is allocated (libFuzzer: a few bytes claimed 9 GiB, an out-of-memory kill);
// a complete file still opens.
TEST(FormatsMetaImageHostile, SizesTheDataCannotHoldAreRefusedBeforeAllocating) {
  TempDir dir;
  const std::string huge =
      "ObjectType = Image\nNDims = 3\nDimSize = 2048 2048 1024\nElementType = MET_SHORT\n";
  test::writeHeaderFile(dir.file("local.mha"), huge + "ElementDataFile = LOCAL\n",
                        std::vector<uint8_t>(48, 1));
  EXPECT_THAT(test::errorMessage([&] { loadVolume(dir.file("local.mha")); }),
              HasSubstr("its header's sizes need 8589934592 bytes of samples, more than the file "
                        "holds"));
  test::writeBytes(dir.file("small.raw"), std::vector<uint8_t>(48, 1));
  test::writeHeaderFile(dir.file("detached.mhd"), huge + "ElementDataFile = small.raw\n");
  EXPECT_THAT(test::errorMessage([&] { loadVolume(dir.file("detached.mhd")); }),
              HasSubstr("more than its data file holds (48 bytes)"));
  test::writeHeaderFile(dir.file("ok.mhd"), hostileMetaImageHeader("small.raw"));
  EXPECT_EQ(loadVolume(dir.file("ok.mhd")).dims, glm::ivec3(4, 3, 2));
}

}  // namespace
}  // namespace voxray
