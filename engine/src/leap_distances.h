#pragma once
// The two-sided leap distances of empty-space skipping: per macro cell the chessboard
// distance in cells to the nearest occupied one, capped at MAX_LEAP (15,
// kernels/empty_space/classify.cl). Three passes on the device, one per axis; a
// transfer-function drag reclassifies every frame.
#include <CL/opencl.hpp>
#include <glm/glm.hpp>

namespace voxray {

struct ContextImpl;

// The distances' cap, as classify.cl's MAX_LEAP.
constexpr int kMaxLeap = 15;

// How the passes run. Sweeps: linear in the cells, one work-item per line (16 lines side by
// side for y and z), what CPUs need. PerCell: one work-item per cell reading 2 MAX_LEAP + 1
// cells, what keeps a GPU's threads busy. Auto: PerCell on GPUs, else Sweeps.
enum class LeapPasses { Auto, Sweeps, PerCell };

// Enqueues the passes: occupancy (1 byte per cell, x fastest, nonzero: occupied) -> out (x),
// out -> scratch (y), scratch -> out (z). out and scratch hold dims' cells at least; occ may
// not be out.
void enqueueLeapDistances(ContextImpl& cl, const cl::Buffer& occ, const cl::Buffer& out,
                          const cl::Buffer& scratch, glm::ivec3 dims,
                          LeapPasses how = LeapPasses::Auto);

}  // namespace voxray
