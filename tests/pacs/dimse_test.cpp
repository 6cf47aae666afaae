// DIMSE against a real Orthanc: C-ECHO, C-FIND, C-GET, C-MOVE, faults.
#include <algorithm>
#include <csignal>
#include <filesystem>

#include <gmock/gmock.h>

#include "pacs_test_support.h"
#include "voxray/io/error.h"

namespace voxray::test {
namespace {

using testing::HasSubstr;

std::vector<PacsMatch> findStudies(const PacsNode& node, PacsQuery q) {
  return makePacsClient(node)->find(q);
}

using DimseTest = PacsTest;

TEST_F(DimseTest, EchoAnswers) { EXPECT_NO_THROW(makePacsClient(server().dimseNode())->echo()); }

TEST_F(DimseTest, WrongCalledAeIsRejectedWithAMessageNamingTheAeTitles) {
  PacsNode node = server().dimseNode();
  node.calledAe = "NOT_ORTHANC";
  EXPECT_THAT(echoFailure(node),
              testing::AllOf(HasSubstr("refused Voxray"), HasSubstr("NOT_ORTHANC")));
}

// The test Orthanc serves DIMSE only to VOXRAY at 127.0.0.1 (orthanc_server.cpp says why).
TEST_F(DimseTest, UnknownCallingAeIsRefused) {
  PacsNode node = server().dimseNode();
  node.callingAe = "STRANGER";
  EXPECT_THAT(echoFailure(node), HasSubstr("refused Voxray"));
}

TEST_F(DimseTest, UnreachableNodeSaysSo) {
  PacsNode node = parsePacsNode("dicom://ORTHANC@127.0.0.1:" + std::to_string(freePort()));
  node.timeoutSec = 5;
  std::string m = echoFailure(node);
  EXPECT_THAT(m, HasSubstr("check that the node is running"));
}

TEST_F(DimseTest, FindByNameDateAndModalityReturnsTheRightStudies) {
  expectStudyQueries(server().dimseNode());
  PacsQuery q;
  q.limit = 1;  // the node is told to stop (C-CANCEL) after the first match
  EXPECT_EQ(findStudies(server().dimseNode(), q).size(), 1u);
}

TEST_F(DimseTest, FindSeriesOfAStudy) {
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = kPhantomStudy;
  auto series = findStudies(server().dimseNode(), q);
  ASSERT_EQ(series.size(), 3u);
  auto volume = std::find_if(series.begin(), series.end(), [](const PacsMatch& m) {
    return m.seriesInstanceUid == kPhantomSeries;
  });
  ASSERT_NE(volume, series.end());
  EXPECT_EQ(volume->numberOfInstances, 28);
  EXPECT_EQ(volume->modalities, "CT");
}

TEST_F(DimseTest, CGetDeliversTheSeriesAsOnDisk) {
  expectRetrievalMatchesDisk(server().dimseNode());
}

TEST_F(DimseTest, CMoveIntoVoxraysReceiverDeliversTheSeriesAsOnDisk) {
  expectRetrievalMatchesDisk(server().moveNode());
}

TEST_F(DimseTest, CancelDuringCGetLeavesNoHalfSeries) {
  expectCancelLeavesNothing(server().dimseNode());
}

TEST_F(DimseTest, CancelDuringCMoveLeavesNoHalfSeries) {
  expectCancelLeavesNothing(server().moveNode());
}

// A server that dies mid C-GET (SIGKILL after 5 of 28 images): a clear error, not a
// cancellation, and no half series in the cache. Its own Orthanc: the suite's stays up.
TEST(DimseFaultTest, ServerKilledDuringCGetLeavesNoHalfSeries) {
  OrthancServer server;
  server.upload(dicomPath("ct-philips-phantom/S2010"));
  PacsCache cache(tempFolder("killed-cache"));
  RetrieveOptions options;
  options.progress = [&](const RetrieveProgress& p) {
    if (p.received == 5) server.stop(SIGKILL);
  };
  auto client = makePacsClient(server.dimseNode());
  std::string message;
  try {
    cache.retrieve(*client, kPhantomStudy, kPhantomSeries, options);
    ADD_FAILURE() << "a retrieval from a killed server returned";
  } catch (const Error& e) {
    EXPECT_NE(e.kind(), Error::Kind::Cancelled) << e.what();
    message = e.what();
  }
  // Which of the two the socket reports (a broken pipe, or the peer gone) is a race.
  EXPECT_THAT(message, testing::AllOf(HasSubstr(server.dimseNode().label()), HasSubstr("C-GET"),
                                      testing::AnyOf(HasSubstr("check that the node is running"),
                                                     HasSubstr("the node ended the connection"))));
  expectNothingCached(cache);
}

}  // namespace
}  // namespace voxray::test
