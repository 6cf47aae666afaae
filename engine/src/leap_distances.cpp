#include "leap_distances.h"

#include "cl_context_impl.h"

namespace voxray {

void enqueueLeapDistances(ContextImpl& cl, const cl::Buffer& occ, const cl::Buffer& out,
                          const cl::Buffer& scratch, glm::ivec3 dims, LeapPasses how) {
  if (how == LeapPasses::Auto) how = cl.info.isGpu ? LeapPasses::PerCell : LeapPasses::Sweeps;
  cl_int4 n = {{dims.x, dims.y, dims.z, 0}};
  auto rounded = [](size_t items) { return cl::NDRange((items + 63) / 64 * 64); };
  cl::CommandQueue& q = cl.queue;
  const size_t cells = size_t(dims.x) * size_t(dims.y) * size_t(dims.z);
  if (how == LeapPasses::PerCell) {
    cl::Kernel pass = cl.kernel("empty_space/classify.cl", "leap_distance", "");
    const cl::Buffer* from[3] = {&occ, &out, &scratch};
    const cl::Buffer* to[3] = {&out, &scratch, &out};
    for (int axis = 0; axis < 3; ++axis) {
      pass.setArg(0, *from[axis]);
      pass.setArg(1, *to[axis]);
      pass.setArg(2, n);
      pass.setArg(3, cl_int(axis));
      pass.setArg(4, cl_int(axis == 0));
      q.enqueueNDRangeKernel(pass, cl::NullRange, rounded(cells), cl::NullRange);
    }
    return;
  }
  // occupancy -> out (z), out -> scratch (y): one work-item per 16 lines side by side along x;
  // scratch -> out (x): one per 16 cells of a line (LEAP_LANES).
  const size_t groups = (size_t(dims.x) + 15) / 16;
  cl::Kernel lanes = cl.kernel("empty_space/classify.cl", "leap_distance_lanes", "");
  for (int axis = 2; axis >= 1; --axis) {
    lanes.setArg(0, axis == 2 ? occ : out);
    lanes.setArg(1, axis == 2 ? out : scratch);
    lanes.setArg(2, n);
    lanes.setArg(3, cl_int(axis));
    lanes.setArg(4, cl_int(axis == 2));
    q.enqueueNDRangeKernel(lanes, cl::NullRange,
                           rounded(groups * size_t(axis == 1 ? dims.z : dims.y)), cl::NullRange);
  }
  cl::Kernel rows = cl.kernel("empty_space/classify.cl", "leap_distance_rows", "");
  rows.setArg(0, scratch);
  rows.setArg(1, out);
  rows.setArg(2, n);
  q.enqueueNDRangeKernel(rows, cl::NullRange, rounded(groups * size_t(dims.y) * size_t(dims.z)),
                         cl::NullRange);
}

}  // namespace voxray
