#pragma once
// Runs body(i) for i in [0, n) on all cores. The first exception is rethrown after every
// worker stopped; a set cancel flag stops handing out work.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace voxray::dicom {

template <class Body>
void parallelFor(size_t n, const Body& body, const std::atomic<bool>* cancel = nullptr) {
  size_t workers = std::min<size_t>(n, std::max(1u, std::thread::hardware_concurrency()));
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto run = [&] {
    for (size_t i; !failed && !(cancel && *cancel) && (i = next++) < n;) {
      try {
        body(i);
      } catch (...) {
        std::lock_guard lock(errorMutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> threads;
  for (size_t w = 1; w < workers; ++w) threads.emplace_back(run);
  run();
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace voxray::dicom
