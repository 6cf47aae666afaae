#pragma once
// A DCMTK transport layer whose connections wait for the node in short slices and give up as
// soon as *cancel becomes true. DCMTK's own waits (the node's answer to an association
// request, each PDU, a full send buffer) block up to the node's timeout (30 s by default), so
// without it a node that takes the TCP connection and never answers holds a cancel that long.
#include <atomic>

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

}  // namespace voxray::pacs
