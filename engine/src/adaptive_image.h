#pragma once
// Image-space adaptive sampling (issue 40, RenderParams::adaptiveImage): a frame marched in two
// passes of the raycast kernel, lattice pixels first, then the blocks whose corners disagree,
// the rest bilinear (kernels/adaptive/image_pass.cl says how). The raycaster sets the raycast
// kernels' arguments; this enqueues the passes, the flags and the fill on its queue.
#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "cl_context_impl.h"
#include "image_lattice.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// Whether a frame of P takes the adaptive passes: asked for (adaptiveImage >= 0).
inline bool wantsAdaptiveImage(const RenderParams& p) { return p.adaptiveImage >= 0.0; }

// How the raycast kernel lays its work-items: one per pixel, or packets of 4 x ROWS pixels.
struct RaycastGrid {
  bool packets = false;
  size_t rows = 1;    // a packet work-item's pixel rows (LANES / 4 x MIP_HALVES)
  cl::NDRange local;  // the raycaster's work-group size (NullRange: the driver's)
};

// iso's depth test between lattice pixels (image_flags.cl's depth_edge): the eye and view
// direction in voxel coordinates (RaycastParams' eye_v, forward_v).
struct ImageDepth {
  bool on = false;
  cl_float4 eye{{0.0f, 0.0f, 0.0f, 0.0f}}, forward{{0.0f, 0.0f, 1.0f, 0.0f}};
  bool ortho = false;
};

class AdaptiveImage {
 public:
  // The lattice pass's hit output for iso's depth test (HIT_OUTPUT), PIXELS float4s.
  const cl::Buffer& hits(ContextImpl& cl, size_t pixels);
  // Enqueues on cl.queue, into OUT (the frame's uchar4 pixels): LATTICE (IMAGE_PASS 1) over
  // the lattice, the flags, REFINE (IMAGE_PASS 2; its argument REFINE_ARG is set here to the
  // flags) over the frame, then the fill. Both kernels' other arguments are the caller's.
  // The events of the four go to EVENTS; the flags are read back for refined() at the next
  // blocking call on the queue.
  void enqueue(ContextImpl& cl, const RenderParams& p, cl::Kernel& lattice, cl::Kernel& refine,
               cl_uint refineArg, const cl::Buffer& out, const RaycastGrid& grid,
               const ImageDepth& depth, std::vector<cl::Event>& events);
  // After the queue finished: blocks of the last frame, and those refined.
  int blocks() const { return int(hostFlags_.size()); }
  int refined() const;

 private:
  cl::Buffer flags_, hits_;
  size_t capacity_ = 0, hitCapacity_ = 0;
  std::vector<uint8_t> hostFlags_;
};

}  // namespace voxray
