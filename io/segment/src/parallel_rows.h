#pragma once
// Splits [0, n) over the machine's cores (the label-map operations are per line or per slice).
#include <algorithm>
#include <functional>
#include <thread>
#include <vector>

namespace voxray {

inline void parallelRange(int n, const std::function<void(int, int)>& body) {
  const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(n, 1));
  if (threads <= 1 || n < 2) {
    body(0, n);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    const int begin = int(int64_t(n) * t / threads), end = int(int64_t(n) * (t + 1) / threads);
    pool.emplace_back([=, &body] { body(begin, end); });
  }
  for (auto& th : pool) th.join();
}

}  // namespace voxray
