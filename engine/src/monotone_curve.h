#pragma once
// A curve through points (x sorted; a repeated x makes a step): straight lines, or the monotone
// piecewise cubic of Fritsch and Carlson with the slopes MATLAB's and SciPy's pchip use. Boost
// 1.74's pchip needs four points and no steps; an opacity tent has three and a preset has
// steps, so the slopes are computed here per run of distinct x.
#include <cstddef>
#include <vector>

namespace voxray {

class MonotoneCurve {
 public:
  MonotoneCurve(std::vector<double> x, std::vector<double> y, bool smooth);
  // The value at t; at a step the value after it. Constant beyond the ends.
  double at(double t) const;
  // The limit from below at t (differs from at(t) only at a step).
  double leftOf(double t) const;

 private:
  double onSegment(std::size_t i, double t) const;
  std::vector<double> x_, y_;
  std::vector<double> slope_;  // at each point, for the run it belongs to
  bool smooth_;
};

}  // namespace voxray
