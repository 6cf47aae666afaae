// DIMSE against a real Orthanc: C-ECHO, C-FIND, C-GET, C-MOVE, faults.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

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

// An unknown series (or study) is named as such, not "incomplete ... try again" (issue 39).
std::string unknownSeriesFailure(const PacsNode& node, const std::string& study) {
  return failure([&] {
    PacsCache cache(tempFolder("cache"));
    auto client = makePacsClient(node);
    cache.retrieve(*client, study, "1.2.3.999");
  });
}

TEST_F(DimseTest, CGetOfAnUnknownSeriesSaysTheNodeHasNoSuchSeries) {
  std::string m = unknownSeriesFailure(server().dimseNode(), kPhantomStudy);
  EXPECT_THAT(m, testing::AllOf(
                     HasSubstr(server().dimseNode().label()), HasSubstr("has no series 1.2.3.999"),
                     testing::Not(HasSubstr("incomplete")), testing::Not(HasSubstr("try again"))));
}

TEST_F(DimseTest, CMoveOfAnUnknownStudySaysTheNodeHasNoSuchStudy) {
  std::string m = unknownSeriesFailure(server().moveNode(), "1.2.3.998");
  EXPECT_THAT(m, testing::AllOf(HasSubstr("has no study 1.2.3.998"),
                                testing::Not(HasSubstr("incomplete"))));
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

// A C-STORE to NODE with a cancel set 0.5 s after it starts: how it failed, and how long
// after the cancel it returned.
struct CancelledSend {
  Error::Kind kind = Error::Kind::Input;
  std::string message;
  double secondsAfterCancel = 0;
};
CancelledSend sendCancelledAfterHalfASecond(const PacsNode& node) {
  std::atomic<bool> cancel{false};
  using Clock = std::chrono::steady_clock;
  Clock::time_point cancelledAt;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    cancelledAt = Clock::now();
    cancel = true;
  });
  CancelledSend send;
  try {
    makePacsClient(node)->store({dicomPath("ct-philips-phantom/S2010/I10")}, &cancel);
    ADD_FAILURE() << "a send to " << node.label() << ", which never answers, returned";
  } catch (const Error& e) {
    send.kind = e.kind();
    send.message = e.what();
  }
  const auto returnedAt = Clock::now();
  canceller.join();
  send.secondsAfterCancel = std::chrono::duration<double>(returnedAt - cancelledAt).count();
  return send;
}

// A node that takes the TCP connection and never answers the association request: a socket
// that listens and never accepts (the kernel completes the handshake for its backlog). A
// cancel during that wait returns within 2 s of being set (the connection looks at the flag
// every 50 ms; the bound leaves room for this loaded machine), not after the node's 30 s
// timeout, and says what happened; nothing was sent.
TEST(DimseStallTest, CancelWhileTheNodeNeverAnswersTheAssociationReturnsAtOnce) {
  int port = 0;
  int listener = loopbackSocket(port, true);
  PacsNode node = parsePacsNode("dicom://STALLED@127.0.0.1:" + std::to_string(port));
  ASSERT_EQ(node.timeoutSec, 30);
  const CancelledSend send = sendCancelledAfterHalfASecond(node);
  close(listener);
  EXPECT_EQ(send.kind, Error::Kind::Cancelled) << send.message;
  EXPECT_THAT(send.message, testing::AllOf(HasSubstr("C-STORE cancelled"), HasSubstr(node.label()),
                                           HasSubstr("had not answered the association request"),
                                           HasSubstr("nothing was exchanged")));
  EXPECT_LT(send.secondsAfterCancel, 2.0);
}

// A host that drops the connection request: a listener whose accept queue (backlog 0) is
// full never answers a further SYN, as a firewall that drops it does.
TEST(DimseStallTest, CancelWhileTheHostDropsTheTcpConnectReturnsAtOnce) {
  int port = 0;
  int listener = loopbackSocket(port, true);
  ASSERT_EQ(listen(listener, 0), 0);
  int filler = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(uint16_t(port));
  ASSERT_EQ(connect(filler, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  PacsNode node = parsePacsNode("dicom://DROPPED@127.0.0.1:" + std::to_string(port));
  const CancelledSend send = sendCancelledAfterHalfASecond(node);
  close(filler);
  close(listener);
  EXPECT_EQ(send.kind, Error::Kind::Cancelled) << send.message;
  EXPECT_THAT(send.message, testing::AllOf(HasSubstr("C-STORE cancelled"), HasSubstr(node.label()),
                                           HasSubstr("had not accepted the TCP connection"),
                                           HasSubstr("nothing was exchanged")));
  // 2 s: the 50 ms poll, with room for a loaded machine; the node's timeout is 30 s.
  EXPECT_LT(send.secondsAfterCancel, 2.0);
}

}  // namespace
}  // namespace voxray::test
