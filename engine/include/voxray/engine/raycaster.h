#pragma once
// The OpenCL raycast pipeline: the volume on the device as 16-bit values, the lookup
// table, and one specialised kernel per combination of features a frame uses.
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"

namespace voxray {

struct Volume;
class ClContext;

enum class VolumeStorage { Auto, Buffer, Image3d };

// How frames are computed; none of it changes the image (beyond float rounding).
struct RaycasterOptions {
  // Specialised: one kernel per combination of features, compiled with -D literals.
  // Uber: one kernel for all, the switches read at runtime (to measure specialisation).
  enum class Kernel { Specialised, Uber } kernel = Kernel::Specialised;
  bool emptySpaceSkipping = true;  // leap macro cells that cannot change the pixel
  bool countSamples = false;       // fill FrameStats::samples (an atomic add per ray)
  // A CPU device with buffer storage: each work-item marches a packet of rays in SIMD
  // (kernels/march/). Ignored elsewhere (GPUs diverge less one ray per work-item).
  bool packets = true;
  // Rays per packet, 8 (4x2) or 16 (4x4). 0: 16 where the device's native float vector
  // holds 16 (AVX-512), else 8, in every mode.
  int packetLanes = 0;
  // Work-group size; 0: 16x8 on GPUs, 4x4 packets with CPU packets, else PoCL's choice.
  int localX = 0, localY = 0;
  // Largest bytes of one z slab of the volume on the device (apron included); 0: the
  // device's largest allocation. Lower it to split volumes that fit (tests, benchmarks).
  size_t maxSlabBytes = 0;
};

struct FrameStats {
  double kernelMs = 0.0;  // from OpenCL profiling events
  double totalMs = 0.0;   // wall time including upload of parameters and read-back
  double samples = 0.0;   // volume samples taken (0 unless RaycasterOptions::countSamples)
  std::string variant;    // the -D options of the kernel that ran
  // shadows, ao: wall time of the light grid's precomputation in this frame (0 when the
  // grid was reused), included in totalMs.
  double lightingMs = 0.0;
  // lighting cinematic (path_tracer.h): samples per pixel accumulated so far, and the
  // seconds they took since the last restart.
  int pathSamples = 0;
  double pathSeconds = 0.0;
};

class Raycaster {
 public:
  // Uploads the volume. Auto storage: image3d_t with hardware filtering on a GPU, a
  // buffer with manual trilinear on a CPU. A volume larger than one allocation or 3D image
  // is split into up to 8 slabs along z. Throws Error (Device) when it still does not fit
  // the device, naming sizes and limits. The volume must outlive the raycaster (on a
  // CPU device the kernels read its voxels in place).
  Raycaster(ClContext& ctx, const Volume& volume, VolumeStorage storage = VolumeStorage::Auto);
  ~Raycaster();
  Raycaster(const Raycaster&) = delete;
  Raycaster& operator=(const Raycaster&) = delete;

  // Lighting cinematic adds one pass of path samples per call to the raycaster's own
  // PathTracer (restarting it when the frame changed) and returns the mean so far.
  Image render(const RenderParams& params, FrameStats* stats = nullptr);
  // The same, into a caller's image (reused between frames: no allocation per frame).
  void render(const RenderParams& params, Image& out, FrameStats* stats = nullptr);
  // Only rows [Y0, Y1) of the frame (the workstation refines its sharp frame in bands, so
  // that a camera move waits for one band, not a whole frame): OUT keeps its other rows
  // when it already has the frame's size. Pixel for pixel the rows of render(PARAMS).
  // Lighting cinematic renders its whole next pass.
  void renderRows(const RenderParams& params, Image& out, int y0, int y1,
                  FrameStats* stats = nullptr);
  // A frame from the -D HIT_OUTPUT=1 variant that also gives each pixel's hit (row by row):
  // xyz the hit point in voxel coordinates, w 1 for an iso surface crossing or where dvr's
  // accumulated opacity reaches 0.5 (DVR_HIT_ALPHA, kernels/march/hit_output.cl: interpolated
  // within the segment that crosses it), 0 for an iso hit at the first sample (entry face
  // or clip cap), -1 for none (a dvr ray that stays below 0.5 or stops earlier by early
  // termination, and every mip pixel).
  Image renderWithHits(const RenderParams& params, std::vector<glm::vec4>& hits,
                       FrameStats* stats = nullptr);

  // The -D options a frame with these parameters compiles with.
  std::string variantOptions(const RenderParams& params) const;
  VolumeStorage storage() const;
  int slabCount() const;  // z slabs the volume is stored in (1: one buffer or image)
  // Uploads the volume again when maxSlabBytes changes (throws as the constructor).
  void setOptions(const RaycasterOptions& options);
  const RaycasterOptions& options() const;
  // Times the occupancy grid was classified (it should follow TF / iso changes only).
  int classifications() const;
  // Of those, the ones that scanned the volume for iso block bits (8-lane iso packets only).
  int isoBlockScans() const;
  // Times the shadows / ao light grid was built (it should follow the light, the transfer
  // function, the clip box and the model only; never a camera move or a phong frame).
  int lightingBuilds() const;
  // Of those, the builds that classified the volume again into the grid's extinction (a
  // light or model change alone reuses it).
  int lightingSigmaBuilds() const;

 private:
  friend struct RaycasterAccess;  // the path tracer shares the device volume and setup
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voxray
