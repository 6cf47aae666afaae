#pragma once
// What the several-device tests share (multi_device_test, multi_device_composite_test): their
// volume and their contexts, made once per process.
#include <map>
#include <memory>
#include <vector>

#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/multi_device.h"

namespace voxray::test {

// 40x36x30, anisotropic: 2, 3 and 4 parts own 15, 10 and 7-8 slices; the ball (z 4.5 to 24.5)
// and its bump cross every boundary obliquely.
inline const Volume& partsBall() {
  static Volume v = ball({40, 36, 30}, 10.0, 1000.0, -1000.0, {1.0, 1.1, 1.3});
  return v;
}

// The contexts of N parts, made once per N (each builds its kernels once).
inline std::vector<ClContext*> partContexts(int n) {
  static std::map<int, std::vector<std::unique_ptr<ClContext>>> made;
  auto& c = made[n];
  if (c.empty()) c = splitDevice(testDeviceSelector(), n);
  std::vector<ClContext*> out;
  for (auto& p : c) out.push_back(p.get());
  return out;
}

}  // namespace voxray::test
