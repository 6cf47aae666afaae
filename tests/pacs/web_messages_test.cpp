// What DICOMweb failures say (issue 39): an unknown series or study named as such, no patient
// data or credentials from a URL, an echo that a redirect or a page that is not DICOM JSON
// does not pass, a caFile that is not a file refused at once.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <gmock/gmock.h>

#include "canned_http_server.h"
#include "pacs_test_support.h"

namespace voxray::test {
namespace {

using testing::AllOf;
using testing::HasSubstr;
using testing::Not;
using WebMessagesTest = PacsTest;

std::string webRetrieveFailure(const PacsNode& node, const std::string& study,
                               const std::string& series) {
  return failure([&] {
    PacsCache cache(tempFolder("cache"));
    auto client = makePacsClient(node);
    cache.retrieve(*client, study, series);
  });
}

TEST_F(WebMessagesTest, UnknownSeriesSaysTheNodeHasNoSuchSeries) {
  const PacsNode node = server().webNode();
  std::string m = webRetrieveFailure(node, kPhantomStudy, "1.2.3.999");
  EXPECT_THAT(m, AllOf(HasSubstr(node.label()), HasSubstr("has no series 1.2.3.999"),
                       Not(HasSubstr("base URL"))));
}

TEST_F(WebMessagesTest, UnknownStudySaysTheNodeHasNoSuchStudy) {
  const PacsNode node = server().webNode();
  std::string m = webRetrieveFailure(node, "1.2.3.998", "1.2.3.999");
  EXPECT_THAT(m, AllOf(HasSubstr("has no study 1.2.3.998"), Not(HasSubstr("base URL"))));
}

// A series search in a study the node does not hold finds nothing, as C-FIND does.
TEST_F(WebMessagesTest, SeriesSearchInAnUnknownStudyFindsNothing) {
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = "1.2.3.998";
  EXPECT_TRUE(makePacsClient(server().webNode())->find(q).empty());
}

// A failed search prints its URL without the query's values (the patient's name and ID) and
// without a token in the node's own query string.
TEST(WebRedactionTest, FailedSearchNamesNoPatientAndNoToken) {
  CannedHttpServer server("HTTP/1.1 500 Internal Server Error\r\nContent-Length: 0\r\n\r\n");
  PacsNode node = server.node();
  node.baseUrl += "?access_token=SECRET-TOKEN";
  PacsQuery q;
  q.patientName = "DOE^JOHN";
  q.patientId = "PID-4711";
  std::string m = failure([&] { makePacsClient(node)->find(q); });
  EXPECT_THAT(
      m, AllOf(HasSubstr("HTTP 500"), HasSubstr("127.0.0.1"), Not(HasSubstr("DOE")),
               Not(HasSubstr("JOHN")), Not(HasSubstr("PID-4711")), Not(HasSubstr("SECRET-TOKEN"))));
  // The node's query goes to the server after the path (the token reached it).
  EXPECT_THAT(server.request, HasSubstr("/dicom-web/studies?"));
  EXPECT_THAT(server.request, HasSubstr("access_token=SECRET-TOKEN"));
}

TEST(WebRedactionTest, LabelHidesCredentialsAndQueryValues) {
  PacsNode node;
  node.transport = PacsNode::Transport::Web;
  node.baseUrl = "https://alice:pa55word@pacs.example/dicom-web?token=SECRET-TOKEN";
  EXPECT_THAT(node.label(), AllOf(HasSubstr("pacs.example/dicom-web"), Not(HasSubstr("alice")),
                                  Not(HasSubstr("pa55word")), Not(HasSubstr("SECRET-TOKEN"))));
}

TEST(WebRedactionTest, UnknownSchemeHidesCredentialsAndQueryValues) {
  std::string m =
      failure([] { parsePacsNode("ftp://alice:pa55word@pacs.example/x?token=SECRET"); });
  EXPECT_THAT(m, AllOf(HasSubstr("pacs.example"), HasSubstr("not a node name or address"),
                       Not(HasSubstr("pa55word")), Not(HasSubstr("SECRET"))));
}

TEST(WebEchoTest, RedirectIsNotAnAnswer) {
  CannedHttpServer server(
      "HTTP/1.1 302 Found\r\nLocation: http://127.0.0.1:1/login\r\nContent-Length: 0\r\n\r\n");
  EXPECT_THAT(echoFailure(server.node()), AllOf(HasSubstr("HTTP 302"), HasSubstr("base URL")));
}

TEST(WebEchoTest, PageThatIsNotDicomJsonIsNotAnAnswer) {
  CannedHttpServer server(CannedHttpServer::answer("200 OK", "text/html", "<html>hi</html>"));
  EXPECT_THAT(echoFailure(server.node()), HasSubstr("not DICOM JSON"));
}

// A caFile that is a FIFO: echo is refused at once, not blocked opening it. A writer that
// opens and closes it every 0.1 s from 3 s on ends such blocks (so the test ends either way).
TEST(WebEchoTest, CaFileThatIsAFifoIsRefusedAtOnce) {
  std::string fifo = tempFolder("fifo") + "/ca.pem";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::atomic<bool> done{false};
  std::thread unblock([&] {
    std::this_thread::sleep_for(std::chrono::seconds(3));
    while (!done) {
      int fd = open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // fails while no reader waits
      if (fd >= 0) close(fd);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  CannedHttpServer server(CannedHttpServer::answer("200 OK", "application/dicom+json", "[]"));
  PacsNode node = server.node();
  node.baseUrl = "https://127.0.0.1:" + std::to_string(server.port) + "/dicom-web";  // TLS reads it
  node.caFile = fifo;
  const auto start = std::chrono::steady_clock::now();
  std::string m = echoFailure(node);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  done = true;
  unblock.join();
  EXPECT_THAT(m, AllOf(HasSubstr("caFile"), HasSubstr("not a regular file")));
  EXPECT_LT(seconds, 2.0);
}

}  // namespace
}  // namespace voxray::test
