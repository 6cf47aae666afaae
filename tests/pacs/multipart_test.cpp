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

// A part over the cap throws as soon as it is known to be (issue 39: a part was kept in
// memory whatever its size); one of the cap's size passes, at every feed size.
TEST(MultipartTest, PartLargerThanTheCapThrows) {
  const std::string atCap = "--XYZ\r\n\r\n" + std::string(100, 'a') + "\r\n--XYZ--\r\n";
  const std::string overCap = "--XYZ\r\n\r\n" + std::string(101, 'a') + "\r\n--XYZ--\r\n";
  for (size_t chunk : {size_t(1), size_t(7), size_t(1000)}) {
    auto feed = [&](const std::string& body) {
      std::vector<std::string> parts;
      MultipartSplitter s(
          "XYZ", [&](const std::string&, std::string c) { parts.push_back(std::move(c)); }, 100);
      for (size_t i = 0; i < body.size(); i += chunk)
        s.feed(body.data() + i, std::min(chunk, body.size() - i));
      s.finish();
      return parts.size();
    };
    EXPECT_EQ(feed(atCap), 1u) << chunk;
    try {
      feed(overCap);
      ADD_FAILURE() << "a part over the cap passed, chunk " << chunk;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("larger than 100 bytes")) << chunk;
    }
  }
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

// Parts of a CT slice's size are handed over in the buffer they arrived in, small ones are
// copied out of it: large and small parts in turn, fed as curl feeds (16 KiB), in one piece
// and byte by byte, come out as they went in.
TEST(MultipartTest, LargeAndSmallPartsComeOutWhole) {
  std::vector<std::string> sent;
  std::string body = "--XYZ\r\n";
  uint32_t x = 12345;
  for (size_t size : {size_t(524288 + 300), size_t(10), size_t(65536), size_t(65535),
                      size_t(200000), size_t(0), size_t(524288 + 300)}) {
    std::string part(size, '\0');
    for (char& c : part) {  // arbitrary bytes, CR, LF and '-' among them
      x = x * 1664525u + 1013904223u;
      c = char(x >> 24);
    }
    sent.push_back(part);
    body += "Content-Type: application/dicom\r\n\r\n" + part + "\r\n--XYZ\r\n";
  }
  body.resize(body.size() - 2);
  body += "--\r\n";
  for (size_t chunk : {size_t(16384), body.size(), size_t(1)}) {
    auto parts = split(body, chunk);
    ASSERT_EQ(parts.size(), sent.size()) << chunk;
    for (size_t i = 0; i < sent.size(); ++i) EXPECT_TRUE(parts[i] == sent[i]) << chunk << " " << i;
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
