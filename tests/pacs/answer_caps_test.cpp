// Caps on what a node may send (issue 39, defect 13): a search stops at FindOptions'
// maxMatches or when a page repeats; a DICOM JSON answer over kMaxAnswerBytes and an HTTP
// error's endless body are not read on.
#include <gmock/gmock.h>

#include <chrono>
#include <fstream>

#include "canned_http_server.h"
#include "http_session.h"
#include "pacs_test_support.h"

namespace voxray::test {
namespace {

using testing::AllOf;
using testing::HasSubstr;
using AnswerCapsTest = PacsTest;

// The third field of /proc/sys/net/ipv4/tcp_[rw]mem: the most a socket buffer may grow to.
size_t tcpBufferMax(const char* path, size_t fallback) {
  std::ifstream in(path);
  size_t low = 0, initial = 0, max = 0;
  return (in >> low >> initial >> max) ? max : fallback;
}
size_t loopbackBuffers() {
  return tcpBufferMax("/proc/sys/net/ipv4/tcp_rmem", size_t(32) << 20) +
         tcpBufferMax("/proc/sys/net/ipv4/tcp_wmem", size_t(4) << 20);
}

// Orthanc holds two studies; a search without a limit and a cap of 1 stops after one.
TEST_F(AnswerCapsTest, SearchWithoutLimitStopsAtTheCap) {
  for (const PacsNode& node : {server().dimseNode(), server().webNode()}) {
    FindOptions options;
    options.maxMatches = 1;
    FindResult r = makePacsClient(node)->findPages(PacsQuery{}, options);
    EXPECT_EQ(r.matches.size(), 1u) << node.label();
    EXPECT_TRUE(r.more) << node.label();
  }
}

// A node that ignores offset sends its first page again: the search ends there (it asked
// without end).
TEST(AnswerCapsWebTest, SearchStopsWhenAPageRepeats) {
  const std::string page =
      R"([{"0020000D":{"vr":"UI","Value":["1.2.3.1"]}},{"0020000D":{"vr":"UI","Value":["1.2.3.2"]}}])";
  CannedHttpServer server(CannedHttpServer::answer("200 OK", "application/dicom+json", page), 4);
  FindOptions options;
  options.pageSize = 2;
  FindResult r = makePacsClient(server.node())->findPages(PacsQuery{}, options);
  ASSERT_EQ(r.matches.size(), 2u);
  EXPECT_EQ(r.matches[1].studyInstanceUid, "1.2.3.2");
  EXPECT_TRUE(r.more);
}

// 256 MiB of "DICOM JSON": refused once 64 MiB came, not read to the end. What the server
// wrote may exceed what the client read by the loopback socket buffers, which Linux tunes up
// to tcp_rmem's and tcp_wmem's maxima (32 + 4 MiB on some machines, 6 + 4 on others): the
// bound is the cap plus those, read from this machine, plus 4 MiB of curl's and the OS's slack.
TEST(AnswerCapsWebTest, SearchAnswerOverTheCapIsRefused) {
  const size_t size = size_t(256) << 20;
  CannedHttpServer server(
      "HTTP/1.1 200 OK\r\nContent-Type: application/dicom+json\r\n"
      "Content-Length: " +
          std::to_string(size) + "\r\n\r\n[",
      1, size - 1);
  std::string m = failure([&] { makePacsClient(server.node())->find(PacsQuery{}); });
  EXPECT_THAT(m, AllOf(HasSubstr("larger than 64 MiB"), HasSubstr("127.0.0.1")));
  EXPECT_LT(server.sent.load(), pacs::kMaxAnswerBytes + loopbackBuffers() + (size_t(4) << 20));
  EXPECT_LT(server.sent.load(), size);
}

// An HTTP 500 with a 256 MiB body: the status is the message; the body is not read on.
TEST(AnswerCapsWebTest, ErrorBodyIsNotReadToTheEnd) {
  const size_t size = size_t(256) << 20;
  CannedHttpServer server(
      "HTTP/1.1 500 Internal Server Error\r\nContent-Type: text/plain\r\n"
      "Content-Length: " +
          std::to_string(size) + "\r\n\r\n",
      1, size);
  std::string m = failure([&] { makePacsClient(server.node())->find(PacsQuery{}); });
  EXPECT_THAT(m, HasSubstr("HTTP 500"));
  // Only the socket buffers (see above) and 4 MiB of slack may have gone out.
  EXPECT_LT(server.sent.load(), loopbackBuffers() + (size_t(4) << 20));
}

// A server that drips its answer, a byte every 0.2 s (a slow loris), never leaves the node's
// timeout idle: before, the search ran as long as the server dripped. It stalls as one that
// sends nothing: given up within the timeout (5 s) and a second, saying why.
TEST(AnswerCapsWebTest, ADrippingServerIsGivenUpAtTheTimeout) {
  CannedHttpServer server(
      "HTTP/1.1 200 OK\r\nContent-Type: application/dicom+json\r\nContent-Length: 100000\r\n\r\n",
      1, 100000, 200);
  const auto start = std::chrono::steady_clock::now();
  std::string m = failure([&] { makePacsClient(server.node())->find(PacsQuery{}); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_THAT(m, HasSubstr("the node sent under 1024 bytes in 5 s (timeout 5 s)"));
  EXPECT_LT(seconds, 5.0 + 1.5);
  EXPECT_LT(server.sent.load(), size_t(300));
}

}  // namespace
}  // namespace voxray::test
