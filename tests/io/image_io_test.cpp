// Writing and reading images: exact round trips, atomic replacement, clear failures.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "test_support.h"
#include "voxray/io/image.h"

namespace voxray {
namespace {

using testing::HasSubstr;

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      uint8_t* p = img.pixel(x, y);
      p[0] = uint8_t(x * 7);
      p[1] = uint8_t(y * 13);
      p[2] = uint8_t(x + y);
      p[3] = uint8_t(255 - x);
    }
  }
  return img;
}

size_t filesIn(const std::filesystem::path& dir) {
  return size_t(std::distance(std::filesystem::directory_iterator(dir), {}));
}

TEST(ImageIo, PngRoundTrip) {
  test::TempDir dir;
  const Image img = gradient(37, 21);
  writeImage(dir.file("out.png"), img);
  const Image back = readImage(dir.file("out.png"));
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 21);
  EXPECT_EQ(back.rgba, img.rgba);
}

TEST(ImageIo, TiffRoundTrip) {
  test::TempDir dir;
  const Image img = gradient(16, 9);
  writeImage(dir.file("out.tif"), img);
  const Image back = readImage(dir.file("out.tif"));
  EXPECT_EQ(back.width, 16);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.rgba, img.rgba);
}

TEST(ImageIo, ExrRoundTripWithinHalfPrecision) {
  test::TempDir dir;
  const Image img = gradient(8, 8);
  writeImage(dir.file("out.exr"), img);
  const Image back = readImage(dir.file("out.exr"));
  ASSERT_EQ(back.rgba.size(), img.rgba.size());
  for (size_t i = 0; i < img.rgba.size(); ++i) EXPECT_NEAR(back.rgba[i], img.rgba[i], 1) << i;
}

TEST(ImageIo, OverwriteIsAtomicAndLeavesNoTemporary) {
  test::TempDir dir;
  writeImage(dir.file("out.png"), gradient(10, 10));
  const Image second = gradient(20, 5);
  writeImage(dir.file("out.png"), second);
  EXPECT_EQ(readImage(dir.file("out.png")).rgba, second.rgba);
  EXPECT_EQ(filesIn(dir.path()), 1u);  // only out.png: no ".out.tmp*.png" left behind
}

TEST(ImageIo, MissingFolderIsAnOutputError) {
  const std::string path = "/nonexistent-voxray-folder/render.png";
  const std::string m =
      test::errorMessage([&] { writeImage(path, gradient(4, 4)); }, Error::Kind::Output);
  EXPECT_THAT(m, HasSubstr(path));
  EXPECT_THAT(m, HasSubstr("does not exist"));
}

TEST(ImageIo, UnknownFormatLeavesNothingBehind) {
  test::TempDir dir;
  const std::string m = test::errorMessage(
      [&] { writeImage(dir.file("render.notaformat"), gradient(4, 4)); }, Error::Kind::Output);
  EXPECT_THAT(m, HasSubstr("render.notaformat"));
  EXPECT_EQ(filesIn(dir.path()), 0u);
}

// A FIFO stays a FIFO and gets the encoded image through it; /dev/null takes one too.
TEST(ImageIo, DevicesAndPipesAreWrittenIntoNotReplaced) {
  test::TempDir dir;
  const std::string fifo = dir.file("pipe.png");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const Image img = gradient(12, 7);
  std::vector<char> received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  });
  writeImage(fifo, img);
  reader.join();
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  std::ofstream(dir.file("copy.png"), std::ios::binary)
      .write(received.data(), std::streamsize(received.size()));
  EXPECT_EQ(readImage(dir.file("copy.png")).rgba, img.rgba);
  EXPECT_EQ(filesIn(dir.path()), 2u);  // the FIFO and the copy: nothing left beside them
  writeImage("/dev/null", img);
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

// Written with OpenImageIO directly: writeImage itself only writes RGBA.
void writeChannels(const std::string& path, int channels, const std::vector<uint8_t>& pixels) {
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(2, 1, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  ASSERT_TRUE(out->open(path, spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  ASSERT_TRUE(out->close());
}

TEST(ImageIo, GrayAndRgbBecomeRgba) {
  test::TempDir dir;
  writeChannels(dir.file("gray.png"), 1, {10, 200});
  EXPECT_EQ(readImage(dir.file("gray.png")).rgba,
            (std::vector<uint8_t>{10, 10, 10, 255, 200, 200, 200, 255}));
  writeChannels(dir.file("rgb.png"), 3, {1, 2, 3, 4, 5, 6});
  EXPECT_EQ(readImage(dir.file("rgb.png")).rgba,
            (std::vector<uint8_t>{1, 2, 3, 255, 4, 5, 6, 255}));
  writeChannels(dir.file("gray-alpha.png"), 2, {7, 100, 9, 0});
  EXPECT_EQ(readImage(dir.file("gray-alpha.png")).rgba,
            (std::vector<uint8_t>{7, 7, 7, 100, 9, 9, 9, 0}));
}

TEST(ImageIo, ReadingMissingOrBrokenFilesIsAnInputError) {
  test::TempDir dir;
  EXPECT_THAT(test::errorMessage([&] { readImage(dir.file("missing.png")); }),
              HasSubstr("missing.png: no such image file"));
  test::writeBytes(dir.file("broken.png"), {0x89, 'P', 'N', 'G', 1, 2, 3});
  EXPECT_THAT(test::errorMessage([&] { readImage(dir.file("broken.png")); }),
              HasSubstr("broken.png: cannot read the image"));
}

}  // namespace
}  // namespace voxray
