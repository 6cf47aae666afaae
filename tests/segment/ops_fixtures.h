#pragma once
// Synthetic volumes for the operation tests: HU from a function of the voxel index.
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "voxray/io/error.h"
#include "voxray/io/segmentation.h"

namespace voxray::test {

inline Volume makeVolume(glm::ivec3 dims, glm::dvec3 spacing,
                         const std::function<int16_t(int, int, int)>& hu) {
  Volume v;
  v.dims = dims;
  v.spacingMm = spacing;
  v.originMm = {-100.0, -50.0, 20.0};
  v.voxels.resize(v.voxelCount());
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) v.voxels[v.index(x, y, z)] = hu(x, y, z);
  return v;
}

// The distance in mm between the centres of two voxels.
inline double mm(const glm::dvec3& spacing, glm::ivec3 a, glm::ivec3 b) {
  const glm::dvec3 d = glm::dvec3(a - b) * spacing;
  return std::sqrt(glm::dot(d, d));
}

// Runs f and returns the message of the voxray::Error it must throw (of `kind`).
template <class F>
std::string errorOf(F&& f, Error::Kind kind = Error::Kind::Input) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(int(e.kind()), int(kind)) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no voxray::Error was thrown";
  return {};
}

inline size_t count(const std::vector<uint8_t>& m) {
  size_t n = 0;
  for (auto b : m) n += b != 0;
  return n;
}

}  // namespace voxray::test
