#pragma once
// A tiny local HTTP server for what Orthanc will not do (cut a transfer short, send garbage,
// fail with 500, redirect): it serves one canned answer to the first connection, then
// closes it.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

#include "voxray/io/pacs.h"

namespace voxray::test {

class CannedHttpServer {
 public:
  explicit CannedHttpServer(std::string answer) : answer_(std::move(answer)) {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len) != 0 || listen(fd_, 1) != 0)
      throw std::runtime_error("cannot listen on 127.0.0.1");
    port = ntohs(addr.sin_port);
    thread_ = std::thread([this] {
      int c = accept(fd_, nullptr, nullptr);
      accepted_ = true;
      char request[4096];
      ssize_t n = read(c, request, sizeof request);
      if (n > 0) this->request.assign(request, size_t(n));
      (void)!write(c, answer_.data(), answer_.size());
      close(c);
    });
  }
  ~CannedHttpServer() {
    // A test that never connected (it failed earlier): connect once so that accept returns.
    if (!accepted_) {
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
  std::string request;  // the first bytes of the request it answered

 private:
  std::string answer_;
  std::atomic<bool> accepted_{false};
  int fd_ = -1;
  std::thread thread_;
};

}  // namespace voxray::test
