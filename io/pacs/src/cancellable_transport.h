#pragma once
// A DCMTK transport layer whose connections wait for the node in short slices, give up as
// soon as *cancel becomes true, and give up once the node has sent nothing for its timeout.
// DCMTK's own waits (the association answer, each PDU, a full send buffer) each block up to
// the timeout and some follow one another (a C-GET's answer, then the abort), or block up to
// DCMTK's 60 s socket timeout (a PDU's rest): a frozen node held a retrieval 2 to 4 times
// the timeout. Here every wait ends by one deadline: the last byte plus the timeout.
#include <atomic>
#include <chrono>
#include <string>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dcmlayer.h>

namespace voxray::pacs {

// When the node last sent or took a byte, shared by every connection of one operation (a
// C-MOVE's association and its receiver's); a wait ends TIMEOUT_SEC after that.
class IdleDeadline {
 public:
  explicit IdleDeadline(int timeoutSec) : timeoutSec_(timeoutSec) { touch(); }
  void touch() { last_ = now(); }
  bool passed() const { return now() - last_.load() >= int64_t(timeoutSec_) * 1000; }
  int timeoutSec() const { return timeoutSec_; }

 private:
  static int64_t now() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  int timeoutSec_;
  std::atomic<int64_t> last_{0};
};

class CancellableTransport : public DcmTransportLayer {
 public:
  // CANCEL may be null (no cancel); IDLE must outlive the connections.
  CancellableTransport(const std::atomic<bool>* cancel, IdleDeadline* idle)
      : cancel_(cancel), idle_(idle) {}
  DcmTransportConnection* createConnection(DcmNativeSocketType socket,
                                           OFBool useSecureLayer) override;

 private:
  const std::atomic<bool>* cancel_;
  IdleDeadline* idle_;
};

// How often a wait looks at the cancel flag: a cancel returns about this long after it is set.
constexpr int kCancelPollMs = 50;

// DCMTK opens the TCP connection inside the association request, before any transport layer
// is asked, and waits for it up to the node's timeout: against a host that drops the
// connection request, a cancel would wait that long. So the connection is first opened here,
// polling *CANCEL, and closed again (DCMTK then opens its own, at once).
enum class ConnectCheck { Connected, Refused, TimedOut, Cancelled };
ConnectCheck checkConnect(const std::string& host, int port, int timeoutSec,
                          const std::atomic<bool>* cancel);

}  // namespace voxray::pacs
