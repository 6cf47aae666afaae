// DICOMweb against a real Orthanc (its DICOMweb plugin): QIDO-RS, WADO-RS, STOW-RS, HTTP
// faults; and a canned local HTTP server for what Orthanc will not do.
#include <gmock/gmock.h>

#include "canned_http_server.h"
#include "pacs_test_support.h"
#include "voxray/io/dicom_import.h"

namespace voxray::test {
namespace {

using testing::HasSubstr;
using WebTest = PacsTest;

TEST_F(WebTest, EchoAnswersWithTheRightPassword) {
  EXPECT_NO_THROW(makePacsClient(server().webNode())->echo());
}

TEST_F(WebTest, WrongPasswordIsHttp401WithAHint) {
  PacsNode node = server().webNode();
  node.password = "wrong-secret";
  std::string m = echoFailure(node);
  EXPECT_THAT(m, HasSubstr("HTTP 401"));
  EXPECT_THAT(m, HasSubstr("set user and password"));
  EXPECT_THAT(m, testing::Not(HasSubstr("wrong-secret")));  // never a password in a message
}

TEST_F(WebTest, WrongBaseUrlIsHttp404WithAHint) {
  PacsNode node = server().webNode();
  node.baseUrl += "-nowhere";
  std::string m = echoFailure(node);
  EXPECT_THAT(m, HasSubstr("HTTP 404"));
  EXPECT_THAT(m, HasSubstr("check the node's base URL"));
}

TEST_F(WebTest, QidoByNameDateAndModalityReturnsTheRightStudies) {
  expectStudyQueries(server().webNode());
  auto client = makePacsClient(server().webNode());
  PacsQuery q;
  // Paging: two pages of one study each, different studies.
  q.limit = 1;
  auto first = client->find(q);
  q.offset = 1;
  auto second = client->find(q);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_NE(first[0].studyInstanceUid, second[0].studyInstanceUid);
}

TEST_F(WebTest, WadoRsDeliversTheSeriesAsOnDisk) { expectRetrievalMatchesDisk(server().webNode()); }

TEST_F(WebTest, CancelDuringWadoRsLeavesNoHalfSeries) {
  expectCancelLeavesNothing(server().webNode());
}

// The import fed each file as it arrives (issue 12's overlap) gives the disk volume, and
// uses what it decoded on the way (it says so).
TEST_F(WebTest, WadoRsImportedAsItArrivesIsTheDiskVolume) {
  PacsCache cache(tempFolder("cache"));
  auto client = makePacsClient(server().webNode());
  std::vector<std::string> said;
  LoadOptions o;
  o.progress = [&](double, const std::string& what) { said.push_back(what); };
  DicomImport import(o);
  CachedSeries entry = cache.retrieve(*client, kPhantomStudy, kPhantomSeries, {}, &import);
  Volume retrieved = import.finish(entry.folder);
  EXPECT_EQ(retrieved.dims, glm::ivec3(512, 512, 28));
  expectSameVolume(retrieved, loadVolume(dicomPath("ct-philips-phantom/S2010")));
  EXPECT_THAT(said, testing::Contains("Decoded 28 slices as they arrived"));
  // The range it knows from the slices (what pacs get reports) is the voxels' own.
  ASSERT_TRUE(import.storedRange().has_value());
  const ValueRange measured = storedRange(retrieved);
  EXPECT_EQ(import.storedRange()->min, measured.min);
  EXPECT_EQ(import.storedRange()->max, measured.max);
  EXPECT_LT(measured.min, measured.max);  // a CT phantom, not a constant
}

TEST_F(WebTest, CancelWhileImportingAsItArrivesLeavesNoHalfSeries) {
  PacsCache cache(tempFolder("cache"));
  std::atomic<bool> cancel{false};
  RetrieveOptions options;
  options.cancel = &cancel;
  options.progress = [&](const RetrieveProgress& p) {
    if (p.received == 5) cancel = true;
  };
  LoadOptions o;
  o.cancel = &cancel;
  DicomImport import(o);
  auto client = makePacsClient(server().webNode());
  try {
    cache.retrieve(*client, kPhantomStudy, kPhantomSeries, options, &import);
    ADD_FAILURE() << "a cancelled retrieval returned";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << e.what();
  }
  expectNothingCached(cache);
  try {
    import.finish(cache.root() + "/series");
    ADD_FAILURE() << "a cancelled import returned";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << e.what();
  }
}

TEST_F(WebTest, StowRsStoresAFileThatQidoThenFinds) {
  auto client = makePacsClient(server().webNode());
  client->store({dicomPath("transfer-syntaxes/1.dcm")});
  PacsQuery q;
  q.modality = "MR";
  EXPECT_EQ(client->find(q).size(), 1u);
}

std::string retrieveFailure(const PacsNode& node) {
  return failure([&] {
    PacsCache cache(tempFolder("cache"));
    auto client = makePacsClient(node);
    cache.retrieve(*client, "1.2.3", "1.2.3.4");
  });
}

TEST(WebFaultTest, ServerStoppingMidTransferIsReportedAndNothingIsKept) {
  std::string part = "--b1\r\nContent-Type: application/dicom\r\n\r\n" + std::string(1000, 'x');
  CannedHttpServer server(
      "HTTP/1.1 200 OK\r\nContent-Type: multipart/related; type=\"application/dicom\"; "
      "boundary=b1\r\nContent-Length: 100000\r\n\r\n" +
      part);
  std::string m = retrieveFailure(server.node());
  EXPECT_THAT(m, HasSubstr("closed the connection before the end"));
}

TEST(WebFaultTest, TruncatedMultipartBodyIsReported) {
  std::string body =
      "--b1\r\nContent-Type: application/dicom\r\n\r\nabc\r\n--b1\r\n"
      "Content-Type: application/dicom\r\n\r\ndef";
  CannedHttpServer server(
      "HTTP/1.1 200 OK\r\nContent-Type: multipart/related; boundary=b1\r\nContent-Length: " +
      std::to_string(body.size()) + "\r\n\r\n" + body);
  std::string m = retrieveFailure(server.node());
  EXPECT_THAT(m, HasSubstr("ended before its closing boundary (1 parts complete)"));
}

TEST(WebFaultTest, GarbageInsteadOfMultipartIsReported) {
  std::string body = "<html>hello</html>";
  CannedHttpServer server("HTTP/1.1 200 OK\r\nContent-Type: text/html\r\nContent-Length: " +
                          std::to_string(body.size()) + "\r\n\r\n" + body);
  std::string m = retrieveFailure(server.node());
  EXPECT_THAT(m, HasSubstr("text/html, not multipart/related"));
}

TEST(WebFaultTest, TlsFailureIsShownNotIgnored) {
  CannedHttpServer server("HTTP/1.1 200 OK\r\nContent-Length: 0\r\n\r\n");  // no TLS at all
  PacsNode node = server.node();
  node.baseUrl = "https://127.0.0.1:" + std::to_string(server.port) + "/dicom-web";
  EXPECT_THAT(echoFailure(node), HasSubstr("TLS failed"));
}

TEST(WebFaultTest, Http500IsReported) {
  CannedHttpServer server("HTTP/1.1 500 Internal Server Error\r\nContent-Length: 0\r\n\r\n");
  std::string m = retrieveFailure(server.node());
  EXPECT_THAT(m, HasSubstr("HTTP 500"));
  EXPECT_THAT(m, HasSubstr("the server failed"));
}

}  // namespace
}  // namespace voxray::test
