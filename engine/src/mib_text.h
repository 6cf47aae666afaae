#pragma once
// A byte count as the multi-device and out-of-core messages print it ("7.62 MiB", "512 MiB").
#include <cstddef>
#include <cstdio>
#include <string>

namespace voxray {

inline std::string mibText(size_t bytes) {
  double m = double(bytes) / double(1 << 20);
  char text[32];
  std::snprintf(text, sizeof(text), m < 10 ? "%.2f MiB" : "%.0f MiB", m);
  return text;
}

}  // namespace voxray
