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

// How the passes run. Sweeps: linear in the cells, each work-item on 16 cells side by side
// along x, what CPUs need. PerCell: one work-item per cell reading 2 MAX_LEAP + 1
// cells, what keeps a GPU's threads busy. Auto: PerCell on GPUs, else Sweeps.
enum class LeapPasses { Auto, Sweeps, PerCell };

// Enqueues the passes from the occupancy (1 byte per cell, x fastest, nonzero: occupied) to
// out, through scratch. out and scratch hold dims' cells at least; occ may not be out.
void enqueueLeapDistances(ContextImpl& cl, const cl::Buffer& occ, const cl::Buffer& out,
                          const cl::Buffer& scratch, glm::ivec3 dims,
                          LeapPasses how = LeapPasses::Auto);

}  // namespace voxray
