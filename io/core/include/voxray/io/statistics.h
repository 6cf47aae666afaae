#pragma once
// Voxray's one median and quantile, for every layer (benchmarks, the lab's sweeps, import,
// the workstation's lighting figures, tests).
#include <vector>

namespace voxray {

// The middle value of VALUES, or the mean of the two middle ones; 0 when VALUES is empty.
double median(std::vector<double> values);

// The nearest-rank Q-quantile of VALUES (Q in [0, 1]): the value at index floor(Q * n) of
// the sorted values, the last one for Q = 1. Always one of VALUES (quantile(v, 0.5) is the
// upper of the two middle values); 0 when VALUES is empty.
double quantile(std::vector<double> values, double q);

}  // namespace voxray
