#pragma once
// A DCMTK transport layer whose connections wait for the node in short slices and give up as
// soon as *cancel becomes true. DCMTK's own waits (the node's answer to an association
// request, each PDU, a full send buffer) block up to the node's timeout (30 s by default), so
// without it a node that takes the TCP connection and never answers holds a cancel that long.
#include <atomic>
#include <string>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dcmlayer.h>

namespace voxray::pacs {

class CancellableTransport : public DcmTransportLayer {
 public:
  explicit CancellableTransport(const std::atomic<bool>* cancel) : cancel_(cancel) {}
  DcmTransportConnection* createConnection(DcmNativeSocketType socket,
                                           OFBool useSecureLayer) override;

 private:
  const std::atomic<bool>* cancel_;
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
