#pragma once
// A tiny local HTTP server for what Orthanc will not do (cut a transfer short, send garbage,
// fail with 500, redirect, send without end or drip a byte at a time): it serves a canned
// answer to each of its first connections, then closes it.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

#include "voxray/io/pacs.h"

namespace voxray::test {

class CannedHttpServer {
 public:
  // Serves ANSWER to each of the first CONNECTIONS connections, followed by TRAILING bytes
  // ('x', written until the client stops reading: an endless body); with DRIP_MS one byte
  // every DRIP_MS milliseconds (a slow loris).
  explicit CannedHttpServer(std::string answer, int connections = 1, size_t trailing = 0,
                            int dripMs = 0)
      : answer_(std::move(answer)),
        connections_(connections),
        trailing_(trailing),
        dripMs_(dripMs) {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len) != 0 || listen(fd_, 4) != 0)
      throw std::runtime_error("cannot listen on 127.0.0.1");
    port = ntohs(addr.sin_port);
    thread_ = std::thread([this] {
      for (int i = 0; i < connections_; ++i) {
        int c = accept(fd_, nullptr, nullptr);
        if (stop_) {
          close(c);
          return;
        }
        ++accepted_;
        char request[4096];
        ssize_t n = read(c, request, sizeof request);
        if (n > 0 && this->request.empty()) this->request.assign(request, size_t(n));
        bool ok = sendAll(c, answer_);
        const std::string chunk(dripMs_ > 0 ? 1 : 64 << 10, 'x');
        for (size_t left = trailing_; ok && left > 0 && !stop_;
             left -= std::min(left, chunk.size())) {
          ok = sendAll(c, chunk.substr(0, std::min(left, chunk.size())));
          if (dripMs_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(dripMs_));
        }
        close(c);
      }
    });
  }
  ~CannedHttpServer() {
    // Connections that never came (a test that failed earlier): connect once so that a
    // waiting accept returns.
    stop_ = true;
    if (accepted_ < connections_) {
      int s = socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in addr{};
      addr.sin_family = AF_INET;
      addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      addr.sin_port = htons(uint16_t(port));
      (void)!connect(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
      close(s);
    }
    thread_.join();
    close(fd_);
  }
  PacsNode node() const {
    PacsNode n = parsePacsNode(address());
    n.timeoutSec = 5;
    return n;
  }
  std::string address() const { return "http://127.0.0.1:" + std::to_string(port) + "/dicom-web"; }
  // An answer with BODY of TYPE and status line STATUS ("200 OK").
  static std::string answer(const std::string& status, const std::string& type,
                            const std::string& body) {
    return "HTTP/1.1 " + status + "\r\nContent-Type: " + type +
           "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  }
  int port = 0;
  std::string request;          // the first bytes of the first request it answered
  std::atomic<size_t> sent{0};  // bytes written to all connections

 private:
  // Writes all of DATA (no SIGPIPE when the client has gone); false once it cannot.
  bool sendAll(int c, const std::string& data) {
    for (size_t done = 0; done < data.size();) {
      ssize_t n = send(c, data.data() + done, data.size() - done, MSG_NOSIGNAL);
      if (n <= 0) return false;
      done += size_t(n);
      sent += size_t(n);
    }
    return true;
  }

  std::string answer_;
  int connections_;
  size_t trailing_;
  int dripMs_;
  std::atomic<bool> stop_{false};
  std::atomic<int> accepted_{0};
  int fd_ = -1;
  std::thread thread_;
};

}  // namespace voxray::test
