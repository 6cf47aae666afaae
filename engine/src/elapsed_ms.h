#pragma once
// The host's millisecond timings of the multi-device and out-of-core renderers: one copy,
// which the files that report them share (and a unity build can merge).
#include <chrono>

namespace voxray {

inline double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace voxray
