#include "cancellable_transport.h"

#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

#include <dcmtk/dcmnet/dcmtrans.h>

namespace voxray::pacs {
namespace {

class CancellableConnection : public DcmTCPConnection {
 public:
  CancellableConnection(DcmNativeSocketType socket, const std::atomic<bool>* cancel,
                        IdleDeadline* idle)
      : DcmTCPConnection(socket), cancel_(cancel), idle_(idle) {}

  // Blocking reads and writes first wait until the socket is ready: DUL then reads or writes
  // what is there, as it would have; a cancel or the idle deadline fails the call as a
  // closed connection does.
  ssize_t read(void* buf, size_t nbyte) override {
    if (!ready(POLLIN, -1)) return failed();
    return moved(DcmTCPConnection::read(buf, nbyte));
  }
  ssize_t write(void* buf, size_t nbyte) override {
    if (!ready(POLLOUT, -1)) return failed();
    return moved(DcmTCPConnection::write(buf, nbyte));
  }
  // DUL's timed waits (DIMSE_NONBLOCKING, the association answer): the same timeout, cut
  // into slices that look at the flag and the deadline.
  OFBool networkDataAvailable(int timeoutSec) override { return ready(POLLIN, timeoutSec); }

 private:
  // True when the socket is ready (or broken: the read or write that follows says so); false
  // on cancel, once the idle deadline has passed, or after TIMEOUT_SEC seconds (negative:
  // only the deadline).
  bool ready(short events, int timeoutSec) {
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::seconds(timeoutSec < 0 ? 0 : timeoutSec);
    for (;;) {
      if ((cancel_ && cancel_->load()) || idle_->passed()) return false;
      pollfd p{getSocket(), events, 0};
      int n = poll(&p, 1, kCancelPollMs);
      if (n > 0 || (n < 0 && errno != EINTR)) return true;
      if (timeoutSec >= 0 && Clock::now() >= deadline) return false;
    }
  }
  ssize_t moved(ssize_t n) {
    if (n > 0) idle_->touch();
    return n;
  }
  ssize_t failed() const {
    errno = cancel_ && cancel_->load() ? ECONNABORTED : ETIMEDOUT;
    return -1;
  }

  const std::atomic<bool>* cancel_;
  IdleDeadline* idle_;
};

}  // namespace

DcmTransportConnection* CancellableTransport::createConnection(DcmNativeSocketType socket,
                                                               OFBool /*useSecureLayer*/) {
  return new CancellableConnection(socket, cancel_, idle_);
}

ConnectCheck checkConnect(const std::string& host, int port, int timeoutSec,
                          const std::atomic<bool>* cancel) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found)
    return ConnectCheck::Refused;  // DCMTK's own attempt says the host is unknown
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSec);
  ConnectCheck result = ConnectCheck::Refused;
  for (addrinfo* a = found; a && result != ConnectCheck::Connected; a = a->ai_next) {
    int s = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (s < 0) continue;
    int rc = connect(s, a->ai_addr, a->ai_addrlen);
    if (rc == 0) result = ConnectCheck::Connected;
    while (rc != 0 && errno == EINPROGRESS) {
      if (cancel && cancel->load()) {
        result = ConnectCheck::Cancelled;
        break;
      }
      if (std::chrono::steady_clock::now() > deadline) {
        result = ConnectCheck::TimedOut;
        break;
      }
      pollfd p{s, POLLOUT, 0};
      if (poll(&p, 1, kCancelPollMs) > 0) {
        int error = 0;
        socklen_t len = sizeof error;
        getsockopt(s, SOL_SOCKET, SO_ERROR, &error, &len);
        if (error == 0) result = ConnectCheck::Connected;
        break;
      }
    }
    close(s);
    if (result == ConnectCheck::Cancelled || result == ConnectCheck::TimedOut) break;
  }
  freeaddrinfo(found);
  return result;
}

}  // namespace voxray::pacs
