// The multipart/related splitter: parts split at every feed size, strict about the grammar.
#include <gmock/gmock.h>

#include "multipart.h"
#include "voxray/io/error.h"

namespace voxray::pacs {
namespace {

using testing::HasSubstr;

const std::string kBody =
    "preamble\r\n--XYZ\r\nContent-Type: application/dicom\r\n\r\nfirst\r\n--XYZ\r\n"
    "Content-Type: application/dicom\r\n\r\n\r\n--XYZ \r\n\r\nthird--XYZ\r\nstill\r\n--XYZ--\r\n"
    "epilogue";

std::vector<std::string> split(const std::string& body, size_t chunk) {
  std::vector<std::string> parts;
  MultipartSplitter s("XYZ",
                      [&](const std::string&, std::string c) { parts.push_back(std::move(c)); });
  for (size_t i = 0; i < body.size(); i += chunk)
    s.feed(body.data() + i, std::min(chunk, body.size() - i));
  s.finish();
  return parts;
}

TEST(MultipartTest, SplitsPartsWhateverTheFeedSize) {
  for (size_t chunk : {size_t(1), size_t(2), size_t(7), size_t(1000)}) {
    auto parts = split(kBody, chunk);
    ASSERT_EQ(parts.size(), 3u) << chunk;
    EXPECT_EQ(parts[0], "first");
    EXPECT_EQ(parts[1], "");
    EXPECT_EQ(parts[2], "third--XYZ\r\nstill");  // a boundary not after CRLF is content
  }
}

TEST(MultipartTest, BoundaryFromContentType) {
  EXPECT_EQ(multipartBoundary("multipart/related; type=\"application/dicom\"; boundary=abc"),
            "abc");
  EXPECT_EQ(multipartBoundary("Multipart/Related; boundary=\"a b;c\"; type=x"), "a b;c");
  EXPECT_THROW(multipartBoundary("multipart/related; type=x"), Error);
  EXPECT_THROW(multipartBoundary("application/json"), Error);
}

TEST(MultipartTest, TruncatedBodyThrowsNamingTheCompleteParts) {
  std::string cut = kBody.substr(0, kBody.find("still"));
  try {
    split(cut, 5);
    FAIL() << "no error for a truncated body";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("ended before its closing boundary (2 parts complete)"));
  }
}

TEST(MultipartTest, TextAfterADelimiterIsRefused) {
  EXPECT_THROW(split("--XYZgarbage\r\n\r\nx\r\n--XYZ--", 3), Error);
}

TEST(MultipartTest, EndlessPreambleIsRefused) {
  EXPECT_THROW(split(std::string(100000, 'a'), 4096), Error);
}

}  // namespace
}  // namespace voxray::pacs
