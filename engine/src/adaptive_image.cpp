#include "adaptive_image.h"

#include <algorithm>
#include <numeric>

namespace voxray {

ImageLattice imageLattice(int width, int height, int k) {
  ImageLattice l;
  l.k = k;
  // Every K-th pixel and the last: ceil((n - 1) / k) intervals.
  l.cols = (std::max(width, 1) - 1 + k - 1) / k + 1;
  l.rows = (std::max(height, 1) - 1 + k - 1) / k + 1;
  return l;
}

namespace {

// The raycast kernel's global size over a W x H grid of pixels (the work-items past it
// return), as Raycaster::render lays the plain frame's.
cl::NDRange globalSize(size_t w, size_t h, const RaycastGrid& g) {
  if (g.packets) {
    w = (w + 3) / 4;
    h = (h + g.rows - 1) / g.rows;
  }
  if (g.local.dimensions() == 2) {
    w = (w + g.local[0] - 1) / g.local[0] * g.local[0];
    h = (h + g.local[1] - 1) / g.local[1] * g.local[1];
  }
  return cl::NDRange(w, h);
}

}  // namespace

const cl::Buffer& AdaptiveImage::hits(ContextImpl& cl, size_t pixels) {
  if (pixels * sizeof(cl_float4) > hitCapacity_) {
    hits_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, pixels * sizeof(cl_float4));
    hitCapacity_ = pixels * sizeof(cl_float4);
  }
  return hits_;
}

void AdaptiveImage::enqueue(ContextImpl& cl, const RenderParams& p, cl::Kernel& lattice,
                            cl::Kernel& refine, cl_uint refineArg, const cl::Buffer& out,
                            const RaycastGrid& grid, const ImageDepth& depth,
                            std::vector<cl::Event>& events) {
  const ImageLattice l = imageLattice(p.width, p.height, p.adaptiveImageSpacing);
  const size_t blocks = size_t(l.blocksX()) * size_t(l.blocksY());
  if (blocks > capacity_) {
    flags_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, blocks);
    capacity_ = blocks;
  }
  hostFlags_.assign(blocks, 0);
  const cl_int4 ip{{l.k, l.cols, l.rows, 0}};
  const cl_int2 size{{p.width, p.height}};
  // The flags and the fill read no volume: one program for every frame.
  cl::Kernel flags = cl.kernel("adaptive/image_flags.cl", "image_flags", "");
  cl::Kernel fill = cl.kernel("adaptive/image_flags.cl", "image_fill", "");
  cl::CommandQueue& q = cl.queue;
  events.assign(4, cl::Event());

  q.enqueueNDRangeKernel(lattice, cl::NullRange, globalSize(size_t(l.cols), size_t(l.rows), grid),
                         grid.local, nullptr, &events[0]);
  flags.setArg(0, out);
  flags.setArg(1, flags_);
  flags.setArg(2, ip);
  flags.setArg(3, size);
  flags.setArg(4, cl_float(p.adaptiveImage));
  flags.setArg(5, depth.on ? hits_ : flags_);  // unread without depth
  flags.setArg(6, cl_int(depth.on));
  flags.setArg(7, depth.eye);
  flags.setArg(8, depth.forward);
  flags.setArg(9, cl_int(depth.ortho));
  q.enqueueNDRangeKernel(flags, cl::NullRange,
                         cl::NDRange(size_t(l.blocksX()), size_t(l.blocksY())), cl::NullRange,
                         nullptr, &events[1]);
  refine.setArg(refineArg, flags_);
  q.enqueueNDRangeKernel(refine, cl::NullRange, globalSize(size_t(p.width), size_t(p.height), grid),
                         grid.local, nullptr, &events[2]);
  // The refine pass's work-items cover 4 x rows pixels (packets) or one: the fill leaves
  // whatever one that ran has written.
  const cl_int2 foot{{grid.packets ? 4 : 1, grid.packets ? cl_int(grid.rows) : 1}};
  fill.setArg(0, out);
  fill.setArg(1, flags_);
  fill.setArg(2, ip);
  fill.setArg(3, size);
  fill.setArg(4, foot);
  q.enqueueNDRangeKernel(fill, cl::NullRange, cl::NDRange(size_t(l.blocksX()), size_t(l.blocksY())),
                         cl::NullRange, nullptr, &events[3]);
  q.enqueueReadBuffer(flags_, CL_FALSE, 0, blocks, hostFlags_.data());
}

int AdaptiveImage::refined() const {
  return int(std::count(hostFlags_.begin(), hostFlags_.end(), uint8_t(1)));
}

}  // namespace voxray
