#pragma once
// The device's half of a sort-last frame (multi_device.h, issue 38): the first part's device
// composites. Each other part writes its image in half floats (8 bytes a pixel, no order),
// read back band by band into pinned memory as its kernel finishes the band, and uploaded to
// the first device, whose kernel (kernels/multidev/composite_parts.cl) composites the band
// with its own float image and writes RGBA8, the only thing read back. The bands overlap the
// transfers with the kernels still running; the host copies nothing pixel by pixel.
#include <cstdint>
#include <vector>

#include "cl_context_impl.h"
#include "frame_bands.h"
#include "voxray/engine/render_params.h"

namespace voxray {

class DeviceCompositor {
 public:
  // The contexts of the parts in the renderer's order; the first composites. They must
  // outlive this.
  explicit DeviceCompositor(const std::vector<ContextImpl*>& contexts);
  ~DeviceCompositor();
  DeviceCompositor(const DeviceCompositor&) = delete;
  DeviceCompositor& operator=(const DeviceCompositor&) = delete;

  // Buffers for frames of PIXELS pixels (kept while frames are no larger).
  void reserve(size_t pixels);
  // Part K's (>= 1) image on its device, the output of its half-float kernel.
  const cl::Buffer& partImage(size_t k) const { return links_[k].device; }

  // A new frame: forgets the last frame's bands.
  void beginFrame();
  // Part K's (>= 1) BAND of a WIDTH-wide frame into pinned host memory once KERNEL is done,
  // on a queue of its own so that its next band's kernel runs meanwhile.
  void readBand(size_t k, int width, const FrameBand& band, const cl::Event& kernel);
  // The compositor's side of BAND, once every part has read it back (the host waits for
  // that): the uploads, the composite after OWNDONE (the first part's kernel of the band) and
  // the band's RGBA8 into OUT (the frame's top row first, 4 bytes a pixel). ORDER: the parts
  // front to back (multi_device.h's visibilityKeys).
  // BANDINDEX: the band's place among this frame's readBand calls.
  void compositeBand(Mode mode, const std::vector<int>& order, glm::vec3 background,
                     float earlyTermination, const cl::Buffer& own, const cl::Event& ownDone,
                     int width, int height, const FrameBand& band, size_t bandIndex, uint8_t* out);
  // Waits for every band's RGBA8 to be on the host.
  void finish();

 private:
  struct Link {  // another part's: its image, where it is read back to, its transfer queue
    ContextImpl* cl = nullptr;
    cl::CommandQueue copies;
    cl::Buffer device, pinned;
    void* host = nullptr;
    std::vector<cl::Event> read;  // per band of the frame in flight
  };
  ContextImpl& first_;
  cl::CommandQueue transfers_;  // the first device's uploads, composites and read-backs
  cl::Buffer others_, rgba_;    // the other parts' images (half) and the frame (RGBA8)
  std::vector<Link> links_;     // [0] unused: the first part's image is its own
  size_t capacity_ = 0;
  void unmap();
};

}  // namespace voxray
