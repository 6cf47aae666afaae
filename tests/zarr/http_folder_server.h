#pragma once
// A real HTTP server on loopback for the OME-Zarr URL tests: serve_folder.py (Python's
// http.server, from the venv) serving a folder at a free port, started here and stopped with
// the object. It logs the path of each GET, so a test can count what a load requested.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace voxray::test {

class HttpFolderServer {
 public:
  HttpFolderServer(const std::string& folder, const std::string& log) : log_(log) {
    if (!std::filesystem::exists(VOXRAY_PYTHON)) {
      error_ = "no Python at " VOXRAY_PYTHON ": run scripts/bootstrap";
      return;
    }
    int out[2];
    if (pipe(out) != 0) {
      error_ = "cannot make a pipe for the server's port";
      return;
    }
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
      close(out[0]);
      close(out[1]);
      execl(VOXRAY_PYTHON, VOXRAY_PYTHON, VOXRAY_SERVE_FOLDER, folder.c_str(), log.c_str(),
            static_cast<char*>(nullptr));
      _exit(127);
    }
    close(out[1]);
    if (pid_ < 0) {
      close(out[0]);
      error_ = "cannot fork the server";
      return;
    }
    // "port N\n" once it listens; 20 s covers a cold Python start on a loaded machine.
    std::string line;
    pollfd p{out[0], POLLIN, 0};
    char c = 0;
    while (line.find('\n') == std::string::npos && poll(&p, 1, 20000) > 0 &&
           read(out[0], &c, 1) == 1)
      line += c;
    close(out[0]);
    if (line.rfind("port ", 0) == 0) port_ = std::stoi(line.substr(5));
    if (port_ <= 0)
      error_ = "the server (" VOXRAY_SERVE_FOLDER ") did not start: it printed '" + line +
               "'; run it by hand to see why";
  }
  ~HttpFolderServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  HttpFolderServer(const HttpFolderServer&) = delete;
  HttpFolderServer& operator=(const HttpFolderServer&) = delete;

  bool started() const { return port_ > 0; }
  const std::string& error() const { return error_; }
  int port() const { return port_; }
  std::string url(const std::string& path) const {
    return "http://127.0.0.1:" + std::to_string(port_) + "/" + path;
  }
  // The paths requested since the last call, in the order they came.
  std::vector<std::string> takeRequests() {
    std::vector<std::string> out;
    std::ifstream in(log_);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    std::ofstream emptied(log_, std::ios::trunc);  // the next call sees only newer requests
    return out;
  }

 private:
  std::string log_, error_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace voxray::test
