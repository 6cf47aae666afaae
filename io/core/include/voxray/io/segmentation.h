#pragma once
// A segmentation: a label map aligned voxel for voxel with its volume (same dims, spacing,
// origin and LPS direction) and the segments its labels name. One label per voxel (as
// ITK-SNAP and a DICOM SEG's labelmap), 0 = no segment, so up to 255 segments. Every layer
// shares this type: the operations and mesh/file writers (io), the raycaster's label-aware
// classification (engine), the workstation's segment editor and the CLI twin (study).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/volume.h"

namespace voxray {

// Where the voxels of a volume or a label map lie in patient space (LPS millimetres).
struct VoxelGrid {
  glm::ivec3 dims{0};
  glm::dvec3 spacingMm{1.0};
  glm::dvec3 originMm{0.0};   // LPS position of the centre of voxel (0,0,0)
  glm::dmat3 direction{1.0};  // columns: LPS unit vectors of the i, j, k axes

  size_t voxelCount() const { return size_t(dims.x) * size_t(dims.y) * size_t(dims.z); }
  size_t index(int x, int y, int z) const {
    return (size_t(z) * size_t(dims.y) + size_t(y)) * size_t(dims.x) + size_t(x);
  }
  // LPS millimetres of a (fractional) voxel index.
  glm::dvec3 toPatient(const glm::dvec3& ijk) const {
    return originMm + direction * (ijk * spacingMm);
  }
  glm::dvec3 toIndex(const glm::dvec3& lps) const {
    return (glm::transpose(direction) * (lps - originMm)) / spacingMm;
  }
  double voxelVolumeMm3() const { return spacingMm.x * spacingMm.y * spacingMm.z; }
};

inline VoxelGrid gridOf(const Volume& v) {
  return VoxelGrid{v.dims, v.spacingMm, v.originMm, v.direction};
}

// Same voxels in the same place, within 1e-4 mm (headers round positions to ~1e-5).
inline bool sameGrid(const VoxelGrid& a, const VoxelGrid& b) {
  if (a.dims != b.dims) return false;
  const auto near = [](const glm::dvec3& p, const glm::dvec3& q, double tol) {
    return glm::all(glm::lessThanEqual(glm::abs(p - q), glm::dvec3(tol)));
  };
  return near(a.spacingMm, b.spacingMm, 1e-4) && near(a.originMm, b.originMm, 1e-4) &&
         near(a.direction[0], b.direction[0], 1e-5) && near(a.direction[1], b.direction[1], 1e-5) &&
         near(a.direction[2], b.direction[2], 1e-5);
}

struct Segment {
  uint8_t label = 1;                    // the value its voxels hold in the label map (1..255)
  std::string name;                     // "Skull"
  glm::vec3 colour{0.9f, 0.85f, 0.7f};  // sRGB 0..1
  float opacity = 1.0f;
  bool visible = true;
  // How a visible segment shows in the 3D view: its colour inside the dvr (label-aware
  // classification), a smooth surface the raycaster draws over the dvr (Raycaster's surface
  // pass), or not at all (the volume there as without the segment). The slice views ignore it.
  enum class Display3d : uint8_t { Volume, Surface, Hidden };
  Display3d display3d = Display3d::Volume;
  // What it is, as a DICOM SEG and Slicer name it: a coded category and type (SNOMED CT
  // code value, scheme designator, meaning) or free text in the meaning alone.
  struct Code {
    std::string value, scheme, meaning;
  };
  Code category{"91723000", "SCT", "Anatomical Structure"};
  Code type;
};

struct Segmentation {
  VoxelGrid grid;
  std::vector<uint8_t> labels;    // grid.voxelCount() values, x fastest, then y, then z
  std::vector<Segment> segments;  // in the order the user sees them

  const Segment* find(uint8_t label) const {
    for (const auto& s : segments)
      if (s.label == label) return &s;
    return nullptr;
  }
};

// An empty segmentation on the volume's grid.
inline Segmentation emptySegmentation(const Volume& v) {
  Segmentation s;
  s.grid = gridOf(v);
  s.labels.assign(s.grid.voxelCount(), 0);
  return s;
}

}  // namespace voxray
