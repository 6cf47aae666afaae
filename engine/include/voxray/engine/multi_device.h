#pragma once
// One frame on several OpenCL devices, sort-last (issue 38, part 4). The volume is split along
// z into one range of slices per device, in proportion to the memory each may use (equal
// devices: equal ranges, equal work for a view along z); each device holds only its range and
// an apron, and marches each pixel's ray over the samples of its range only
// (kernels/multidev/raycast_part.cl): the samples of the one-device frame (the ray's global
// entry, step and jitter), each taken by exactly one device: the range's planes z = first and
// z = end (voxel coordinates, slice centres at integers) cut each ray into index ranges,
// half-open along the ray (a sample on a plane belongs to the range the ray enters there),
// computed alike by both neighbours of a plane. The partial images are composited in the
// order the ray meets the ranges: "over" of premultiplied colour for dvr, max for mip, the
// nearest hit for iso; by render() on the first device (the others' images come to it in half
// floats, band by band: MultiDeviceOptions::composite), by the host from renderParts' floats.
//
// Equal to one device's frame (Raycaster with packets off, the same scalar march) within one
// 8-bit level per channel, except where dvr's early termination cuts a ray: a device whose
// range starts partway along a ray does not know the opacity in front of it, so it marches on
// past the point where the one-device ray stopped. What it adds there is weighted by the
// transmittance left at that point, at most 1 - earlyTermination (the composite stops adding
// ranges once the sum reaches earlyTermination), so dvr differs by at most
// 1 - earlyTermination per channel (2.55 levels at the default 0.99) plus one level. The
// device composite's half floats (relative error at most 2^-11: 0.25 of a level after "over")
// can add one level more.
//
// Phong lighting; dvr, iso and mip; empty-space skipping, jitter, every gradient and
// interpolation. Adaptive steps are off in the parts (segments grouped from a range's start
// would differ from the whole ray's); labels, an overlay, shadows, ao and cinematic are the
// one-device Raycaster's (render throws Error (Input) for the lighting).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "voxray/engine/render_params.h"
#include "voxray/engine/volume_storage.h"
#include "voxray/io/image.h"
#include "voxray/io/volume.h"  // ValueRange

namespace voxray {

struct Volume;
class ClContext;

// Slices [first, end) a device owns and [storedFirst, storedEnd) it holds (apron included).
struct PartRange {
  int first = 0, end = 0;
  int storedFirst = 0, storedEnd = 0;
};

// One part's image on the host (kernels/multidev/raycast_part.cl): per pixel premultiplied
// RGBA (4 floats, without the background) and the index its range starts at along the ray
// (dvr) or of its hit (iso), FLT_MAX where it has none, which orders the parts per pixel.
// Top row first. The memory is the renderer's, valid until its next frame.
struct PartImage {
  const float* colour = nullptr;
  const float* order = nullptr;
};

struct MultiDeviceOptions {
  bool emptySpaceSkipping = true;
  // Slices each device stores beyond its range on either side. The stencils read floor(z) - 1
  // to floor(z) + 2 (slab_plan.h's apron of 2), and a sample the index rule gives a range
  // may lie up to one step (iso's refinement: from the sample before) beyond its plane: 4
  // keeps every read exact for steps up to 2 slices; render throws Error (Input) for a
  // longer step (it would read the clamped edge of the stored slices).
  int apron = 4;
  // Bytes one device may hold for its slices (0: its largest allocation). Lower it to see
  // what a device too small for its range does (a test, a budget the user sets).
  size_t budgetBytes = 0;
  // Auto: image3d_t on GPUs with image support, else a buffer (as the Raycaster's Auto).
  VolumeStorage storage = VolumeStorage::Auto;
  // The ranges of the parts, one per context, instead of planParts' split of the volume: an
  // MPI rank renders its one range (app/mpi). Empty: planParts by memory.
  std::vector<PartRange> ranges;
  // Where render() composites. Device: on the first device: the other parts write their
  // images in half floats (8 bytes a pixel, no order: the slabs' order serves every pixel),
  // read back and uploaded to it band by band of rows while the kernels run on, and its kernel
  // composites them with its own part and writes RGBA8, the only thing read back (at most 8
  // parts; more composite on the host). Host: every part's float image and order read back
  // and composited on the host (renderParts always gives these). The device composite differs
  // from the host's by the half floats alone (relative error at most 2^-11 per value: at most
  // 0.25 of an 8-bit level after "over", so at most one level) and where that moves dvr's
  // sum across earlyTermination (at most 1 - earlyTermination more).
  enum class Composite { Device, Host };
  Composite composite = Composite::Device;
  // Bands of rows the device composite pipelines (0: by the height, about 256 rows a band).
  int bands = 0;
  // Each device holds the whole volume where every one can (its largest allocation, the
  // budget), and before each frame the planes between the ranges move so that the last
  // frame's kernel times, spread evenly over each range's slices, would have been equal (a
  // view's cost is rarely even along z). Ignored with `ranges` or where the volume does not
  // fit: the ranges stay planParts'.
  bool balance = false;
  // The whole volume's stored value range (the tables map it), when VOLUME holds the stored
  // slices of the ranges alone and the rest is filler (an MPI rank's slab). None: VOLUME's.
  std::optional<ValueRange> valueRange;
  // An MPI rank's slab alone (app/mpi): VOLUME is the whole volume's geometry without voxels
  // (withoutVoxels) and SLAB holds its slices [slabFirst, slabFirst + slab->dims.z), which
  // must take in every range's stored slices; valueRange is then required. The empty-space
  // cells are those of the whole volume with the slices outside the slab at valueRange->min
  // (what they were when a rank held the whole volume's size, filled). SLAB must outlive the
  // renderer. Null: VOLUME holds every slice.
  const Volume* slab = nullptr;
  int slabFirst = 0;
};

// DIMZ slices into weights.size() contiguous ranges in proportion to WEIGHTS (each > 0), each
// at least one slice, with APRON slices more stored on each side (clamped to the volume).
// Throws Error (Input) when there are more ranges than slices or no weights.
std::vector<PartRange> planParts(int dimZ, const std::vector<double>& weights, int apron);

struct PartStats {
  std::string device;  // its name
  PartRange range;
  // The device's profiled kernel time: its first band's start to its last band's end.
  double kernelMs = 0.0;
  // From the frame's start until its image was on the host (host composite) or its kernel
  // done (device composite).
  double readyMs = 0.0;
};

struct MultiDeviceStats {
  std::vector<PartStats> parts;
  // The composite alone: the host's, or with the device composite the time from the last
  // part's kernel finishing to the frame on the host.
  double compositeMs = 0.0;
  bool deviceComposite = false;  // the frame was composited on the first device
  double totalMs = 0.0;
  std::string variant;  // the parts' -D options
};

class MultiDeviceRenderer {
 public:
  // One part per context (two may share a device); the contexts and VOLUME must outlive the
  // renderer. Uploads each range. Throws Error (Device) naming the device, its range and the
  // bytes when a range exceeds the device's largest allocation (or 3D image) or the budget.
  MultiDeviceRenderer(const std::vector<ClContext*>& contexts, const Volume& volume,
                      const MultiDeviceOptions& options = {});
  ~MultiDeviceRenderer();
  MultiDeviceRenderer(const MultiDeviceRenderer&) = delete;
  MultiDeviceRenderer& operator=(const MultiDeviceRenderer&) = delete;

  // The frame on every device at once, then composited into OUT (RGBA8).
  void render(const RenderParams& params, Image& out, MultiDeviceStats* stats = nullptr);
  Image render(const RenderParams& params, MultiDeviceStats* stats = nullptr) {
    Image out;
    render(params, out, stats);
    return out;
  }
  // The parts' images of the frame, not composited (an MPI rank's part, composited by IceT).
  std::vector<PartImage> renderParts(const RenderParams& params, MultiDeviceStats* stats = nullptr);
  // Per part, a key that orders the parts front to back for every pixel of the frame at once
  // (lower: nearer). The ranges are z slabs: with a parallel projection every ray meets them in
  // the order of its direction's z; from an eye, a ray meets only the slabs on one side of the
  // eye's z, nearest first, so the distance from the eye's z to each slab orders them.
  std::vector<double> visibilityKeys(const RenderParams& params);
  // Where render() composites from now on (MultiDeviceOptions::composite).
  void setComposite(MultiDeviceOptions::Composite where);
  int partCount() const;
  std::vector<PartRange> ranges() const;

 private:
  // The frame on every part: composited into OUT and/or the parts' images into PARTS.
  void renderInto(const RenderParams& params, Image* out, MultiDeviceStats* stats,
                  std::vector<PartImage>* parts);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Contexts for PARTS parts on the device SELECTOR names (ClContext's selectors): its equal
// sub-devices where it can be split so (a CPU under PoCL), else PARTS contexts on the one
// device (each part then shares it).
std::vector<std::unique_ptr<ClContext>> splitDevice(const std::string& selector, int parts);

}  // namespace voxray
