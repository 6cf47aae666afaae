#include "label_grid.h"

#include <array>
#include <cmath>
#include <sstream>

#include "voxray/io/error.h"
#include "whole_file.h"

namespace voxray::segfiles {
namespace {

// Distinct, light enough to read on CT grey (Slicer's first generic-anatomy colours).
constexpr std::array<std::array<float, 3>, 8> kPalette{{{0.50f, 0.68f, 0.50f},
                                                        {0.94f, 0.84f, 0.57f},
                                                        {0.69f, 0.48f, 0.39f},
                                                        {0.44f, 0.72f, 0.82f},
                                                        {0.85f, 0.40f, 0.40f},
                                                        {0.87f, 0.51f, 0.89f},
                                                        {0.56f, 0.93f, 0.56f},
                                                        {0.98f, 0.98f, 0.82f}}};

// Whole voxel offset of FILE's first voxel in ONTO's grid when FILE is a box of ONTO's
// lattice (same spacing and axes), else nothing.
bool boxOffset(const VoxelGrid& file, const VoxelGrid& onto, glm::ivec3& offset) {
  VoxelGrid shifted = onto;
  const glm::dvec3 at = onto.toIndex(file.originMm);
  const glm::dvec3 whole = glm::round(at);
  if (glm::any(glm::greaterThan(glm::abs(at - whole), glm::dvec3(1e-3)))) return false;
  offset = glm::ivec3(whole);
  if (glm::any(glm::lessThan(offset, glm::ivec3(0))) ||
      glm::any(glm::greaterThan(offset + file.dims, onto.dims)))
    return false;
  shifted.dims = file.dims;
  shifted.originMm = onto.toPatient(whole);
  return sameGrid(shifted, file);
}

}  // namespace

std::string labelValueProblem(double value, const std::string& path) {
  if (value >= 0 && value <= 255 && value == std::floor(value)) return {};
  std::ostringstream s;
  s << path << ": holds the value " << value
    << ", which is not a label (whole numbers 0 to 255); is it an image rather than a label map?";
  return s.str();
}

Segmentation placeOnVolume(LabelFile file, const Volume& onto, const std::string& path) {
  Segmentation seg = emptySegmentation(onto);
  glm::ivec3 offset(0);
  if (sameGrid(file.grid, seg.grid)) {
    seg.labels = std::move(file.labels);
  } else if (boxOffset(file.grid, seg.grid, offset)) {
    const glm::ivec3 d = file.grid.dims;
    for (int z = 0; z < d.z; ++z)
      for (int y = 0; y < d.y; ++y)
        for (int x = 0; x < d.x; ++x)
          seg.labels[seg.grid.index(x + offset.x, y + offset.y, z + offset.z)] =
              file.labels[file.grid.index(x, y, z)];
  } else {
    checkOnGrid(file.grid, seg.grid, path);  // throws, naming the difference
  }
  std::array<bool, 256> present{};
  for (uint8_t l : seg.labels) present[l] = true;
  std::array<bool, 256> named{};
  for (auto& s : file.segments) {
    if (s.label == 0 || named[s.label]) continue;  // checkSegmentation's rules: skip, not fail
    named[s.label] = true;
    seg.segments.push_back(s);
  }
  for (int l = 1; l < 256; ++l) {
    if (!present[size_t(l)] || named[size_t(l)]) continue;
    Segment s;
    s.label = uint8_t(l);
    s.name = "Label " + std::to_string(l);
    const auto& c = kPalette[size_t(l - 1) % kPalette.size()];
    s.colour = {c[0], c[1], c[2]};
    seg.segments.push_back(s);
  }
  return seg;
}

}  // namespace voxray::segfiles
