#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <mutex>

namespace voxray::cli {

std::function<void(double, const std::string&)> terminalProgress(const std::string& what) {
  if (!isatty(STDERR_FILENO)) return {};
  auto mutex = std::make_shared<std::mutex>();
  auto last = std::make_shared<int>(-1);
  return [=](double fraction, const std::string& message) {
    std::lock_guard<std::mutex> lock(*mutex);
    int pct = int(fraction * 100.0 + 0.5);
    if (pct == *last) return;
    *last = pct;
    std::fprintf(stderr, "\r%s: %3d%% %s\033[K", what.c_str(), pct, message.c_str());
    if (pct >= 100) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  };
}

}  // namespace voxray::cli
