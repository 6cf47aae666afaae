#pragma once
// A minimal parallel loop for the io layer. Loads and phantoms are rare, large jobs, so
// starting a few std::threads per call costs nothing worth a thread pool.
#include <functional>

namespace voxray::detail {

// Runs body(i) for every i in [0, count) on up to hardware_concurrency threads. If bodies
// throw, the remaining indices are skipped and the exception of the lowest index is
// rethrown after every thread has stopped, so errors do not depend on scheduling.
void parallelFor(int count, const std::function<void(int)>& body);

}  // namespace voxray::detail
