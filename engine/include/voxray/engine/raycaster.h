#pragma once
// The OpenCL raycast pipeline: the volume on the device as 16-bit values, the lookup
// table, and one specialised kernel per combination of features a frame uses.
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"
#include "voxray/engine/renderer.h"
#include "voxray/engine/volume_storage.h"
#include "voxray/io/image.h"

namespace voxray {

struct Volume;
struct Segmentation;
class ClContext;
struct DeviceFrame;
class PathTracer;
struct PathTracerOptions;

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

// Volumes put on a device by any raycaster of this process so far (each raycaster's upload,
// each re-upload of setOptions), for tests of what shares one (the workstation's movie
// export renders on the view's, issue 40 item 6).
int deviceVolumeUploads();

class Raycaster : public Renderer {
 public:
  // Uploads the volume. Auto storage: image3d_t with hardware filtering on a GPU, a
  // buffer with manual trilinear on a CPU. A volume larger than one allocation or 3D image
  // is split into up to 8 slabs along z. Throws Error (Device) when it still does not fit
  // the device, naming sizes and limits. The volume must outlive the raycaster (on a
  // CPU device the kernels read its voxels in place).
  Raycaster(ClContext& ctx, const Volume& volume, VolumeStorage storage = VolumeStorage::Auto);
  ~Raycaster() override;
  Raycaster(const Raycaster&) = delete;
  Raycaster& operator=(const Raycaster&) = delete;

  // The renderer of a frame with PARAMS: this raycaster, or for lighting cinematic its own
  // PathTracer (made on first use), which adds one pass of path samples per frame.
  Renderer& rendererFor(const RenderParams& params);
  // The options of that path tracer (restarts it; throws as PathTracer::setOptions).
  void setPathTracerOptions(const PathTracerOptions& options);

  using Renderer::render;
  // Phong, shadows and ao (lighting cinematic throws Error (Input): ask rendererFor).
  void render(const RenderParams& params, Image& out, FrameStats* stats = nullptr) override;
  // Only rows [Y0, Y1) of the frame (the workstation refines its sharp frame in bands, so
  // that a camera move waits for one band, not a whole frame): OUT keeps its other rows
  // when it already has the frame's size. Pixel for pixel the rows of render(PARAMS).
  void renderRows(const RenderParams& params, Image& out, int y0, int y1,
                  FrameStats* stats = nullptr) override;
  // A frame from the -D HIT_OUTPUT=1 variant that also gives each pixel's hit (row by row):
  // xyz the hit point in voxel coordinates, w 1 for an iso surface crossing or where dvr's
  // accumulated opacity reaches 0.5 (DVR_HIT_ALPHA, kernels/march/hit_output.cl: interpolated
  // within the segment that crosses it), 0 for an iso hit at the first sample (entry face
  // or clip cap), -1 for none (a dvr ray that stays below 0.5 or stops earlier by early
  // termination, and every mip pixel).
  Image renderWithHits(const RenderParams& params, std::vector<glm::vec4>& hits,
                       FrameStats* stats = nullptr);

  // Label-aware dvr (issue 34): SEG's label map goes to the device beside the volume and
  // its segments' colours, opacities and visibility into the segment table, so that dvr
  // frames show each visible segment in its colour (RenderParams::segmentBlend) and
  // RenderParams::segmentMask shows only, or hides, what segments cover. A frame whose
  // segments and mask change nothing (no segment, none visible, blend 0 and mask off)
  // renders as without a segmentation. The light grid (shadows, ao) and the path tracer
  // ignore the labels. Throws Error (Input) when SEG's grid is not the volume's, Error
  // (Device) when its label map exceeds one allocation.
  void setSegmentation(const Segmentation& seg);
  // After an edit of SEG (set before): its segments again, and its label map within the
  // voxel box LO ... HI (inclusive, clamped to the volume; an empty box, LO above HI along an
  // axis: the segments only).
  void updateSegmentation(const Segmentation& seg, glm::ivec3 lo, glm::ivec3 hi);
  void clearSegmentation();
  bool hasSegmentation() const;

  // Segments shown as surfaces (Segment::display3d Surface, visible; the first 8 in the
  // list): dvr frames draw each as the smooth 0.5 level of its occupancy field (the mask
  // filtered by a Gaussian of sigmaVoxels per axis, engine/src/surface_field.h), shaded with
  // the field's gradient in the segment's colour and opacity, composited into the dvr at its
  // depth (kernels/surface/surface_layer.cl). The fields are built in setSegmentation and
  // updateSegmentation (the caller's thread and parallelFor's: the workstation's render
  // thread), again only where an edit of the label map touches them; a camera move builds
  // nothing. Sigma 0: the mask itself (blocky; the tests' comparison). Rebuilds the fields.
  void setSurfaceSigma(float sigmaVoxels);
  // Times a segment's field was built (for tests: edits of the labels only).
  int surfaceFieldBuilds() const;
  // Each pixel's nearest surface hit of a frame with PARAMS (dvr), row by row: the world
  // point (mm, LPS from the volume centre) and the outward unit normal the shading used;
  // label 0 where no surface is hit.
  struct SurfaceHit {
    glm::vec3 pointMm{0.0f};
    glm::vec3 normal{0.0f};
    int label = 0;
  };
  std::vector<SurfaceHit> surfaceHits(const RenderParams& params);

  // Fused dvr (issue 36, voxray/engine/overlay.h): OVERLAY (e.g. PET on this CT) goes to the
  // device with its own table TF (over its physical values), and every dvr frame then
  // classifies both volumes at each sample's patient point and mixes them by summed
  // extinction (kernels/march/march.cl). Its grid is its own (origin, spacing, direction);
  // it shows only inside this volume's box (where the rays march). Returns what the user
  // should know (overlayWarnings: no shared Frame of Reference). Throws Error (Device) when
  // its voxels exceed one allocation. iso, mip, the light grid and the path tracer ignore it.
  std::vector<std::string> setOverlay(const Volume& overlay, const TransferFunction& tf);
  void clearOverlay();
  bool hasOverlay() const;

  // The volume on the device and the frame set up on it, which a PathTracer shares.
  std::shared_ptr<DeviceFrame> deviceFrame() const;

  // The -D options a frame with these parameters compiles with.
  std::string variantOptions(const RenderParams& params) const;
  VolumeStorage storage() const;
  int slabCount() const;  // z slabs the volume is stored in (1: one buffer or image)
  // Wall times of the constructor's upload (ms): the volume to the device (a re-upload of
  // setOptions replaces it) and the empty-space tables built from it (bench --first-image).
  struct UploadTimes {
    double volumeMs = 0.0, emptySpaceMs = 0.0;
  };
  UploadTimes uploadTimes() const;
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
  // A drag with the light following the camera (issue 40 item 4): while held, a shadows
  // grid is kept when the light moved only with the camera, so a drag frame costs what phong
  // does instead of a grid build per frame (a table, clip box, model or camera-relative light
  // change still rebuilds, and so does a light turned 45 degrees from the grid's). Such a frame is
  // lit by the current light, its shadows those of the light where the grid was built (the
  // drag's start: shadows stay put on the anatomy while the highlights follow the camera).
  // Releasing changes nothing by itself; the next frame rebuilds for its light and is then
  // byte for byte the frame an unheld raycaster renders. The workstation holds it for its
  // interactive frames, `voxray-cli bench --drag` for its replay.
  void holdLightGrid(bool hold);
  bool lightGridHeld() const;
  // Frames rendered with a held grid built for another light than theirs.
  int lightingHeldFrames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voxray
