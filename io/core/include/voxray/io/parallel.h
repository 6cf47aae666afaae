#pragma once
// Voxray's one parallel loop, for every layer (io, engine's macro cells and reference
// renderer). Calls are rare and large (a load, a phantom, a reference frame), so a few
// std::threads per call cost nothing worth a thread pool.
#include <atomic>
#include <cstddef>
#include <functional>

namespace voxray {

// Runs body(i) for every i in [0, count) on up to hardware_concurrency threads, the calling
// thread among them. Indices are handed out in increasing order, one at a time.
// Errors: once a body throws, no further index is handed out; after every thread has
// stopped, the exception of the lowest failing index is rethrown on the caller's thread
// (the one a serial loop would have thrown, whatever the scheduling); the others are dropped.
// Cancellation: once *CANCEL is true no further index is handed out and the call returns
// normally when the bodies in progress end; the caller reports the cancellation.
void parallelFor(size_t count, const std::function<void(size_t)>& body,
                 const std::atomic<bool>* cancel = nullptr);

}  // namespace voxray
