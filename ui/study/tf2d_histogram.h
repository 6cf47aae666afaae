#pragma once
// The 2D transfer-function editor's background (issue 35): how many voxels have each
// (value in HU, gradient magnitude in HU/mm), the plane the rectangles and triangles of a Tf2d
// are drawn on (Kniss et al.: boundaries arc up from the materials' values at |gradient| 0).
// The gradient is the kernels' shading gradient: central differences in mm on the voxel grid,
// a clamped neighbour at the volume's faces (the sampler clamps there too).
#include <atomic>
#include <cstdint>
#include <vector>

#include "no_qt.h"

namespace voxray {

struct Volume;

struct Tf2dHistogram {
  static constexpr int kValueBins = 256;
  static constexpr int kGradientBins = 64;
  double huLo = 0.0, huHi = 1.0;  // the value axis: the volume's HU range
  double gradientMax = 1.0;       // the gradient axis: 0 ... this HU/mm (the top row holds above)
  // counts[row * kValueBins + column], row 0 = |gradient| 0.
  std::vector<uint64_t> counts;
  uint64_t total = 0;
  bool empty() const { return counts.empty(); }
  uint64_t at(int column, int row) const {
    return counts[size_t(row) * kValueBins + size_t(column)];
  }
  // The bin of HU and of |gradient| G (clamped to the axes).
  int columnOf(double hu) const;
  int rowOf(double g) const;
  // log(1 + count) / log(1 + the largest count): 0 ... 1, the grey the editor draws.
  std::vector<float> logImage() const;
};

// Counts V on every core. GRADIENT_MAX 0: the axis' top is the 99th percentile of |gradient|
// over a sparse sample (every 4th voxel along each axis), rounded up to a multiple of 8 HU/mm,
// so that a few extreme edges (metal, air-bone) do not squeeze the rest into the bottom rows.
// Returns an empty histogram when *CANCEL turns true.
Tf2dHistogram tf2dHistogram(const Volume& v, double gradientMax = 0.0,
                            const std::atomic<bool>* cancel = nullptr);

}  // namespace voxray
