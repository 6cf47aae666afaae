#pragma once
// What the raycaster and the path tracer both render from, held by both: the volume on the
// device, the last frame's setup, and the frame parameters and table uploaded for it.
#include <optional>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "cl_context_impl.h"
#include "device_volume.h"
#include "frame_setup.h"
#include "kernel_params.h"
#include "kernel_switches.h"
#include "voxray/engine/volume_storage.h"
#include "voxray/io/volume.h"

namespace voxray {

struct DeviceFrame {
  ContextImpl& cl;
  const Volume& volume;
  VolumeStorage storage;  // Auto until upload() resolves it
  DeviceVolume device;
  cl::Buffer paramsBuffer;
  cl::Buffer lutBuffer;
  size_t lutCapacity = 0;
  int lutAllocations = 0;  // counts new table buffers (what was copied after the table is gone)
  // The last frame's setup. Its table and thresholds do not depend on the camera, the image
  // size or the step, so an orbit, and a drag frame and the sharp one after it, only
  // recompute the view and the step.
  FrameSetup setup;
  std::optional<SetupKey> setupKey;  // what the table and thresholds were made from
  // The volume's stored value range, found once: a pass over a 512x512x400 CT took 85 ms of
  // each transfer-function edit (issue 35).
  std::optional<ValueRange> valueRange;

  DeviceFrame(ContextImpl& c, const Volume& v, VolumeStorage s) : cl(c), volume(v), storage(s) {}

  // The volume (resolving Auto storage) and the parameter buffer to the device.
  void upload(size_t maxSlabBytes);
  // PREINT: also the pre-integrated table (FrameSetup::preint) for P's step, made again only
  // when the colour table or the step changed; without, none.
  void updateSetup(const RenderParams& p, bool preint = false);
  // The frame's kernel parameters from the current setup (cells left 0: the raycaster's
  // macro-cell grid fills them).
  RaycastParams frameParams(const RenderParams& p, const KernelSwitches& sw) const;
  // The parameters and table to the device (the table only when it changed). EXTRA: bytes
  // after the tables in their buffer (the shadows / ao light grid, at tableBytes()).
  void uploadFrame(const RaycastParams& k, size_t extraBytes = 0);
  // The colour table's bytes and the gradient-opacity table's (gradient_table.h), the 2D
  // transfer function's (tf2d_table.h) or the pre-integrated one's (preint_table.h) behind it.
  size_t tableBytes() const;

 private:
  std::vector<glm::vec4> lutUploaded;     // the table on the device: uploaded on change only
  std::vector<float> gradientUploaded;    // likewise the gradient-opacity table
  std::vector<glm::vec4> tf2dUploaded;    // and the 2D transfer function's
  std::vector<glm::vec4> preintUploaded;  // and the pre-integrated table
  RaycastParams paramsUploaded{};
};

}  // namespace voxray
