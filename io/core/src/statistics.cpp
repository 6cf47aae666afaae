#include "voxray/io/statistics.h"

#include <algorithm>
#include <cstddef>

namespace voxray {

double median(std::vector<double> values) {
  const size_t n = values.size();
  if (n == 0) return 0.0;
  auto mid = values.begin() + std::ptrdiff_t(n / 2);
  std::nth_element(values.begin(), mid, values.end());
  if (n % 2) return *mid;
  return 0.5 * (*std::max_element(values.begin(), mid) + *mid);
}

double quantile(std::vector<double> values, double q) {
  const size_t n = values.size();
  if (n == 0) return 0.0;
  const size_t at = std::min(n - 1, size_t(std::clamp(q, 0.0, 1.0) * double(n)));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(at), values.end());
  return values[at];
}

}  // namespace voxray
