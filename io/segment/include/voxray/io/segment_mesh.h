#pragma once
// The closed surface of one segment, in LPS millimetres: what the STL/OBJ/PLY writers write,
// the 3D view draws and the statistics take the surface area from. Made with VTK's flying
// edges and windowed-sinc smoothing and meshoptimizer's simplifier (or VTK's DecimatePro for
// a topology-preserving result); no VTK type appears here.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/segmentation.h"

namespace voxray {

struct SurfaceOptions {
  // Windowed-sinc smoothing (VTK, normalised coordinates, as 3D Slicer): 0 iterations = the
  // raw voxel staircase. A lower pass band smooths more.
  int smoothingIterations = 20;
  double passBand = 0.01;
  // Simplify to at most this many triangles (0 = keep all): printers and viewers choke on the
  // millions a bone gives.
  size_t targetTriangles = 500000;
  // meshoptimizer is ~50x faster than VTK's decimators but may pinch the surface where two
  // sheets meet; true uses vtkDecimatePro with PreserveTopology for a manifold result (tens of
  // seconds on a bone; it may stop short of the target where topology forbids collapses).
  bool preserveTopology = false;
};

// Where the time of one makeSurface went, for the bench: seconds of wall clock and of CPU
// (all threads; on a shared machine the CPU time says what the wall time would be alone).
struct SurfaceTimings {
  struct Stage {
    double wall = 0, cpu = 0;
  };
  Stage crop, extract, decimate, smooth, finish;
  // CPU seconds of meshoptimizer in its slabs' threads: the longest is the stage's critical path.
  double slabCpuMax = 0, slabCpuSum = 0;
  size_t extractedTriangles = 0;  // flying edges' output, before simplification
};

struct SegmentSurface {
  uint8_t label = 0;
  std::vector<glm::vec3> vertices;  // LPS mm
  std::vector<uint32_t> indices;    // 3 per triangle, counter-clockwise seen from outside
  double areaMm2 = 0;
  double volumeMm3 = 0;  // enclosed (divergence theorem), > 0
  size_t triangleCount() const { return indices.size() / 3; }
};

// The surface of the voxels labelled LABEL. Throws an input Error when the segmentation is
// malformed, the label names no segment, or the segment has no voxels.
SegmentSurface makeSurface(const Segmentation& s, uint8_t label, const SurfaceOptions& options = {},
                           SurfaceTimings* timings = nullptr);

// Edges counted by how many triangles share them: a closed manifold surface has every edge in
// exactly two triangles, running opposite ways (consistent orientation).
struct EdgeCount {
  size_t edges = 0;
  size_t boundary = 0;     // in one triangle: a hole
  size_t nonManifold = 0;  // in three or more
  size_t misoriented = 0;  // in two triangles that run it the same way
  bool closedManifold() const {
    return edges > 0 && boundary == 0 && nonManifold == 0 && misoriented == 0;
  }
};
EdgeCount countEdges(const SegmentSurface& surface);

}  // namespace voxray
