#pragma once
// How many voxels of a segmentation hold LABEL (the segment editor's tests).
#include <cstddef>
#include <cstdint>

#include "voxray/io/segmentation.h"

namespace voxray::test {

inline size_t countLabel(const Segmentation& s, uint8_t label) {
  size_t n = 0;
  for (uint8_t l : s.labels) n += l == label;
  return n;
}

}  // namespace voxray::test
