#pragma once
// What the path tracer shares with the Raycaster it is made from: the volume on the device,
// the frame setup (view, table, thresholds) and the uploaded frame parameters and table.
#include <CL/opencl.hpp>

#include "cl_context_impl.h"
#include "device_volume.h"
#include "frame_setup.h"
#include "kernel_switches.h"
#include "voxray/engine/raycaster.h"

namespace voxray {

class PathTracer;

struct SharedFrame {
  ContextImpl& cl;
  const Volume& volume;
  const DeviceVolume& device;
  const FrameSetup& setup;
  const cl::Buffer& params;  // RaycastParams of p, uploaded
  const cl::Buffer& lut;     // the setup's table, uploaded
  KernelSwitches switches;   // the one-ray-per-work-item switches params was built with
};

struct RaycasterAccess {
  // Updates the raycaster's setup for p and uploads p's frame parameters and table. The
  // references stay valid until the raycaster's next frame.
  static SharedFrame prepare(Raycaster& r, const RenderParams& p);
  // The raycaster's own path tracer (Raycaster::render with lighting cinematic).
  static PathTracer& cinematic(Raycaster& r);
};

// Raycaster::render for lighting cinematic (path_tracer.cpp).
void renderCinematic(Raycaster& r, const RenderParams& p, Image& out, FrameStats* stats);

}  // namespace voxray
