// A folder import reads each uncompressed 16-bit frame from where the header scan stopped
// (FrameHeader::pixelValueOffset) without parsing the file a second time; the bytes there
// must still say "pixel data, this long" or the file is parsed as before.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "../io/test_support.h"
#include "dicom_writer.h"
#include "frame_header.h"
#include "pixel_decode.h"

namespace voxray {
namespace {

constexpr int kSize = 256;
constexpr size_t kPixelBytes = size_t(kSize) * kSize * 2;

std::string writeSlice(test::TempDir& dir, bool implicitVr, bool trailing) {
  test::TestSlice s;
  s.size = kSize;
  s.allWords = true;  // pixel i holds word i
  s.implicitVr = implicitVr;
  s.trailingPadding = trailing;
  const std::string path = dir.file("slice.dcm");
  test::writeTestSlice(path, s);
  return path;
}

dicom::FrameHeader scan(const std::string& path) {
  std::vector<dicom::FrameHeader> frames;
  std::string why;
  EXPECT_EQ(dicom::readFrameHeaders(path, frames, why), dicom::ScanResult::Image) << why;
  EXPECT_EQ(frames.size(), 1u);
  return frames.empty() ? dicom::FrameHeader{} : frames[0];
}

// Whether OUT holds word i at pixel i, and the first pixel where it does not.
::testing::AssertionResult everyWordInPlace(const std::vector<uint16_t>& out) {
  for (size_t i = 0; i < out.size(); ++i)
    if (out[i] != uint16_t(i))
      return ::testing::AssertionFailure() << "pixel " << i << " holds " << out[i];
  return ::testing::AssertionSuccess();
}

// Frame H of PATH through NativeFrames: whether it was read, and every word in place if so.
::testing::AssertionResult readsEveryWord(const std::string& path, const dicom::FrameHeader& h) {
  std::vector<uint16_t> out(size_t(kSize) * kSize, 0xDEAD);
  dicom::NativeFrames native(path);
  if (!native.read(h, out.data())) return ::testing::AssertionFailure() << "not read";
  return everyWordInPlace(out);
}

// Overwrites COUNT bytes of PATH at AT with 'X'.
void scribble(const std::string& path, long at, size_t count) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(at);
  const std::string x(count, 'X');
  f.write(x.data(), std::streamsize(count));
}

TEST(DicomDirectPixels, TheScanStopsWhereThePixelValueStarts) {
  for (bool implicitVr : {false, true}) {
    SCOPED_TRACE(implicitVr ? "implicit VR" : "explicit VR");
    test::TempDir dir;
    const std::string path = writeSlice(dir, implicitVr, false);
    const dicom::FrameHeader h = scan(path);
    // The pixel data is the last element: its value is the file's last 128 KiB.
    EXPECT_EQ(h.pixelValueOffset, std::filesystem::file_size(path) - kPixelBytes);
  }
}

// With the file's start destroyed after the scan a second parse would fail; the frame is
// still read, so it came from the scan's offset.
TEST(DicomDirectPixels, FramesAreReadWithoutASecondParse) {
  for (bool implicitVr : {false, true})
    for (bool trailing : {false, true}) {
      SCOPED_TRACE(std::string(implicitVr ? "implicit" : "explicit") +
                   (trailing ? ", trailing element" : ""));
      test::TempDir dir;
      const std::string path = writeSlice(dir, implicitVr, trailing);
      const dicom::FrameHeader h = scan(path);
      scribble(path, 0, 200);
      EXPECT_TRUE(readsEveryWord(path, h));
    }
}

// An offset that does not point just past the pixel data's tag, VR and length (a file
// rewritten since the scan) is not trusted: the file is parsed and read as before.
TEST(DicomDirectPixels, AnOffsetThatIsNotThePixelDataIsNotUsed) {
  test::TempDir dir;
  const std::string path = writeSlice(dir, false, false);
  const dicom::FrameHeader scanned = scan(path);
  for (uint64_t offset : {uint64_t(0), uint64_t(12), uint64_t(300), scanned.pixelValueOffset + 2,
                          scanned.pixelValueOffset - 2, uint64_t(1) << 40}) {
    SCOPED_TRACE(offset);
    dicom::FrameHeader h = scanned;
    h.pixelValueOffset = offset;
    EXPECT_TRUE(readsEveryWord(path, h));
  }
}

// A pixel value the file no longer holds in full (cut short after the scan) is not read
// from the offset, and the parser then refuses the short frame too: no frame half read.
TEST(DicomDirectPixels, APixelValueTheFileCannotHoldIsNotRead) {
  test::TempDir dir;
  const std::string path = writeSlice(dir, false, false);
  const dicom::FrameHeader h = scan(path);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 2);
  std::vector<uint16_t> out(size_t(kSize) * kSize, 0xDEAD);
  dicom::NativeFrames native(path);
  EXPECT_FALSE(native.read(h, out.data()));
}

}  // namespace
}  // namespace voxray
