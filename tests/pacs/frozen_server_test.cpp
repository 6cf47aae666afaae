// A server frozen (SIGSTOP) before or during a retrieval: C-GET, C-MOVE and WADO-RS give up
// about the node's timeout after the last data (issue 39, defect 2: C-GET waited twice the
// timeout, C-MOVE the timeout + 60 s), say the timeout they waited, and keep nothing. Each
// test has its own Orthanc: the frozen one is thawed and stopped.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <iostream>

#include <gmock/gmock.h>

#include "pacs_test_support.h"

namespace voxray::test {
namespace {

using testing::HasSubstr;
using Clock = std::chrono::steady_clock;

constexpr int kTimeoutSec = 5;

struct Frozen {
  std::string message;
  Error::Kind kind = Error::Kind::Input;
  // From the freeze or the last image that arrived, whichever came later (what the server
  // had sent into the socket buffers still arrives after the freeze).
  double secondsAfterLastData = 0;
};

int64_t ticks() { return Clock::now().time_since_epoch().count(); }

// Retrieves the phantom series from NODE (timeout 5 s), freezing SERVER once FREEZE_AFTER
// images have arrived (0: before the retrieval starts).
Frozen retrieveFrozen(OrthancServer& server, PacsNode node, int freezeAfter) {
  node.timeoutSec = kTimeoutSec;
  PacsCache cache(tempFolder("frozen-cache"));
  std::atomic<int64_t> frozenAt{0}, lastData{0};
  auto freeze = [&] {
    server.freeze();
    frozenAt = ticks();
  };
  RetrieveOptions options;
  options.progress = [&](const RetrieveProgress& p) {  // C-MOVE: the receiver's thread
    lastData = ticks();
    if (p.received == freezeAfter && frozenAt == 0) freeze();
  };
  if (freezeAfter == 0) freeze();
  Frozen f;
  try {
    auto client = makePacsClient(node);
    cache.retrieve(*client, kPhantomStudy, kPhantomSeries, options);
    ADD_FAILURE() << "a retrieval from a frozen server returned";
  } catch (const Error& e) {
    f.message = e.what();
    f.kind = e.kind();
  }
  const auto returned = Clock::now();
  server.thaw();
  EXPECT_NE(frozenAt.load(), 0) << "the server was never frozen";
  const int64_t from = std::max(frozenAt.load(), lastData.load());
  f.secondsAfterLastData =
      std::chrono::duration<double>(returned - Clock::time_point(Clock::duration(from))).count();
  std::cout << "gave up " << f.secondsAfterLastData << " s after the last data\n";
  expectNothingCached(cache);
  return f;
}

void expectGaveUpInTime(const Frozen& f, const PacsNode& node) {
  EXPECT_EQ(f.kind, Error::Kind::Input) << f.message;
  EXPECT_THAT(f.message,
              testing::AllOf(HasSubstr(node.label()),
                             HasSubstr("timeout " + std::to_string(kTimeoutSec) + " s")));
  // The issue allows the timeout + 5 s; + 3 s here, so that twice the timeout (10 s) fails
  // with this short one.
  EXPECT_LT(f.secondsAfterLastData, kTimeoutSec + 3.0) << f.message;
  EXPECT_GT(f.secondsAfterLastData, kTimeoutSec - 0.5) << f.message;  // it waited the timeout
}

class FrozenServerTest : public testing::Test {
 protected:
  void SetUp() override { server_.upload(dicomPath("ct-philips-phantom/S2010")); }
  OrthancServer server_;
};

TEST_F(FrozenServerTest, CGetGivesUpWithinTheTimeoutWhenTheServerFreezesMidway) {
  expectGaveUpInTime(retrieveFrozen(server_, server_.dimseNode(), 5), server_.dimseNode());
}

TEST_F(FrozenServerTest, CGetGivesUpWithinTheTimeoutWhenTheServerIsFrozenBefore) {
  expectGaveUpInTime(retrieveFrozen(server_, server_.dimseNode(), 0), server_.dimseNode());
}

TEST_F(FrozenServerTest, CMoveGivesUpWithinTheTimeoutWhenTheServerFreezesMidway) {
  expectGaveUpInTime(retrieveFrozen(server_, server_.moveNode(), 5), server_.moveNode());
}

TEST_F(FrozenServerTest, CMoveGivesUpWithinTheTimeoutWhenTheServerIsFrozenBefore) {
  expectGaveUpInTime(retrieveFrozen(server_, server_.moveNode(), 0), server_.moveNode());
}

TEST_F(FrozenServerTest, WadoRsGivesUpWithinTheTimeoutWhenTheServerFreezesMidway) {
  expectGaveUpInTime(retrieveFrozen(server_, server_.webNode(), 5), server_.webNode());
}

}  // namespace
}  // namespace voxray::test
