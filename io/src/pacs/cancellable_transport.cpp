#include "cancellable_transport.h"

#include <poll.h>

#include <cerrno>
#include <chrono>

#include <dcmtk/dcmnet/dcmtrans.h>

namespace voxray::pacs {
namespace {

class CancellableConnection : public DcmTCPConnection {
 public:
  CancellableConnection(DcmNativeSocketType socket, const std::atomic<bool>* cancel)
      : DcmTCPConnection(socket), cancel_(cancel) {}

  // Blocking reads and writes first wait until the socket is ready: DUL then reads or writes
  // what is there, as it would have; a cancel fails the call as a closed connection does.
  ssize_t read(void* buf, size_t nbyte) override {
    if (!ready(POLLIN, -1)) return cancelled();
    return DcmTCPConnection::read(buf, nbyte);
  }
  ssize_t write(void* buf, size_t nbyte) override {
    if (!ready(POLLOUT, -1)) return cancelled();
    return DcmTCPConnection::write(buf, nbyte);
  }
  // DUL's timed waits (DIMSE_NONBLOCKING, the association answer): the same timeout, cut
  // into slices that look at the flag.
  OFBool networkDataAvailable(int timeoutSec) override { return ready(POLLIN, timeoutSec); }

 private:
  // True when the socket is ready (or broken: the read or write that follows says so); false
  // on cancel or after TIMEOUT_SEC seconds (negative: no timeout).
  bool ready(short events, int timeoutSec) {
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::seconds(timeoutSec < 0 ? 0 : timeoutSec);
    for (;;) {
      if (cancel_->load()) return false;
      pollfd p{getSocket(), events, 0};
      int n = poll(&p, 1, kCancelPollMs);
      if (n > 0 || (n < 0 && errno != EINTR)) return true;
      if (timeoutSec >= 0 && Clock::now() >= deadline) return false;
    }
  }
  static ssize_t cancelled() {
    errno = ECONNABORTED;
    return -1;
  }

  const std::atomic<bool>* cancel_;
};

}  // namespace

DcmTransportConnection* CancellableTransport::createConnection(DcmNativeSocketType socket,
                                                               OFBool /*useSecureLayer*/) {
  return new CancellableConnection(socket, cancel_);
}

}  // namespace voxray::pacs
