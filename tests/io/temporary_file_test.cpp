// temporaryBeside: the hidden name every whole-or-nothing writer (images, movies, DICOM
// objects, segmentation files) writes before its rename.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "voxray/io/temporary_file.h"

namespace voxray {
namespace {

const std::string kPid = std::to_string(::getpid());

// The call counter's part of a name ".stem.tmpPID-N.ext", as a number.
unsigned counterOf(const std::string& name, const std::string& stem, const std::string& ext) {
  const std::string head = "." + stem + ".tmp" + kPid + "-";
  EXPECT_EQ(name.compare(0, head.size(), head), 0) << name;
  EXPECT_EQ(name.compare(name.size() - ext.size(), ext.size(), ext), 0) << name;
  return unsigned(std::stoul(name.substr(head.size(), name.size() - head.size() - ext.size())));
}

TEST(TemporaryBeside, HiddenInTheSameFolderWithTheExtensionKept) {
  const auto t = temporaryBeside("/data/out/shot.png");
  EXPECT_EQ(t.parent_path(), "/data/out");  // the same file system: rename is atomic
  counterOf(t.filename().string(), "shot", ".png");
  EXPECT_EQ(temporaryBeside("shot.png").parent_path(), "");  // a bare name stays bare
}

TEST(TemporaryBeside, AWholeExtensionOfTwoPartsIsKept) {
  const auto nii = temporaryBeside("/d/mask.nii.gz", ".nii.gz").filename().string();
  counterOf(nii, "mask", ".nii.gz");
  const auto seg = temporaryBeside("/d/Seg.SEG.NRRD", ".seg.nrrd").filename().string();
  counterOf(seg, "Seg", ".seg.nrrd");  // the extension as given; the stem by its length
  const auto none = temporaryBeside("/d/README", "").filename().string();
  counterOf(none, "README", "");
}

TEST(TemporaryBeside, EachCallGetsANewName) {
  const std::string a = temporaryBeside("/d/x.dcm").filename().string();
  const std::string b = temporaryBeside("/d/x.dcm").filename().string();
  EXPECT_EQ(counterOf(b, "x", ".dcm"), counterOf(a, "x", ".dcm") + 1);
}

}  // namespace
}  // namespace voxray
