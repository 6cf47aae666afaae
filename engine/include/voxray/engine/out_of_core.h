#pragma once
// A volume larger than the device, or than a memory budget the user sets, on ONE device (issue
// 38 part 2). The volume is planned as z-range parts (multi_device.h's parts: each marches only
// its samples of the one-device ray), more than the budget holds; only as many as fit are on
// the device at once. A converged frame renders every part in visibility order, uploading
// those missing (evicting others), and composites each into an accumulator on the device as it
// comes (kernels/multidev/accumulate_part.cl): one image is read back a frame, and the next
// part's slices are read from the source while the device renders. A preview frame (an
// orbit, a drag) uploads nothing: it draws the parts on the device at full resolution and the
// others from a coarse level over the same z range, and says it is not at full resolution.
//
// The converged frame equals MultiDeviceRenderer's frame of the same volume (and so the
// one-device frame) within the bound multi_device.h states: the parts are its parts, the
// composite its "over", max and nearest hit in the order the ray meets the slabs.
//
// Which part leaves the device: the one needed again latest (Belady's rule, with the next
// frame taken to visit the parts in this frame's order). LRU would evict, on every upload of a
// frame that visits the parts in order, exactly the part the next frame needs first: with k of
// n parts held it uploads all n every frame; this uploads n - k once the frame before has
// filled the device.
//
// The slices come from a SlabSource (slab_source.h), read per part and released after upload;
// the empty-space cells and the value range come from one streamed pass over the source when
// the renderer is made.
//
// How a part reaches a GPU (OutOfCoreOptions::upload, Pinned): its slices are read into host
// staging the runtime pins (two buffers made with CL_MEM_ALLOC_HOST_PTR and mapped once, used
// in turn) and copied by a non-blocking write on a transfer queue of its own; the part's
// kernel waits for that copy's event. Part i + 1 is read and copied while part i's kernel
// runs. Pageable memory went through the driver's own staging copy (about 1.2 GB/s on an
// H200 against 20-50 GB/s pinned), each copy after the queue had drained.
#include <memory>
#include <string>
#include <vector>

#include "voxray/engine/multi_device.h"  // PartRange
#include "voxray/engine/render_params.h"
#include "voxray/engine/slab_source.h"
#include "voxray/engine/volume_storage.h"
#include "voxray/io/image.h"

namespace voxray {

class ClContext;

struct OutOfCoreOptions {
  // Device bytes the renderer may hold: the resident parts' slices, the coarse level and the
  // empty-space cells (the frame's image buffers come on top). 0: the device's largest
  // allocation.
  size_t budgetBytes = 0;
  // Slices each part owns; 0: chosen so that about 8 parts (at least 1) fit the budget.
  int partSlices = 0;
  bool emptySpaceSkipping = true;
  int apron = 4;  // as MultiDeviceOptions::apron
  VolumeStorage storage = VolumeStorage::Auto;
  // How the parts' slices reach the device. Direct: from the slices in host memory where the
  // source has them (a CPU device then reads them in place, no copy), else from one staging
  // copy, with a blocking copy once the queue has drained. Pinned: through the pinned
  // staging ring and the transfer queue (the header's note). Auto: Pinned on a GPU, Direct on
  // a CPU device (where "pinned" memory is ordinary memory and in-place slices copy nothing).
  enum class Upload { Auto, Direct, Pinned };
  Upload upload = Upload::Auto;
  // A fault hook (tests): the device takes at most this many parts at once, whatever the
  // budget says; an upload beyond fails as an allocation on a full device does. -1: no limit.
  int faultDeviceParts = -1;
};

struct OutOfCoreStats {
  bool fullResolution = true;      // false: some parts were drawn from the coarse level
  bool deviceOutOfMemory = false;  // an upload failed in this frame (the rest drawn coarse)
  int parts = 0;                   // of the plan
  int partsResident = 0;           // on the device after the frame
  int partsFull = 0;               // drawn at full resolution in this frame
  int partsCoarse = 0;  // drawn from the coarse level in this frame (full + coarse = parts)
  int uploads = 0;      // parts uploaded in this frame
  size_t bytesUploaded = 0;
  double readMs = 0.0;    // reading the uploaded parts' slices from the source (host wall)
  double uploadMs = 0.0;  // their copies to the device: Pinned, the copies' profiled device
                          // time; Direct, the host's wall time of the blocking copies
  double kernelMs = 0.0;  // the frame's launches (parts, coarse runs, their composite), profiled
  // From the frame's first part to its last part's composite done, on the host's clock. What
  // of read + upload + kernel ran at the same time as something else of it: their sum less
  // partsMs (0 when they ran one after another; the time between them, the host's enqueueing
  // and waits, counts against it).
  double partsMs = 0.0;
  double overlapMs = 0.0;
  bool pinned = false;  // the frame's uploads went through the pinned staging ring
  double totalMs = 0.0;
  std::string message;  // what went wrong when deviceOutOfMemory, for the user
};

class OutOfCoreRenderer {
 public:
  // CONTEXT and SOURCE must outlive the renderer. Reads the source once (the empty-space cells
  // and the value range), uploads the coarse level. Throws Error (Input) when the budget cannot
  // hold one part (naming the budget, the bytes one part needs and the budget to ask for), and
  // Error (Device) when the coarse level cannot be uploaded.
  OutOfCoreRenderer(ClContext& context, SlabSource& source, const OutOfCoreOptions& options = {});
  ~OutOfCoreRenderer();
  OutOfCoreRenderer(const OutOfCoreRenderer&) = delete;
  OutOfCoreRenderer& operator=(const OutOfCoreRenderer&) = delete;

  // The full-resolution frame: every part, uploading the missing ones. When the device fails
  // an allocation, the frame's parts not on it are drawn coarse instead and the stats say so;
  // the budget then shrinks to what the device held, and the next frames converge within it.
  void render(const RenderParams& params, Image& out, OutOfCoreStats* stats = nullptr);
  // The resident parts at full resolution, the others from the coarse level; uploads nothing.
  void preview(const RenderParams& params, Image& out, OutOfCoreStats* stats = nullptr);

  int partCount() const;
  int residentCount() const;
  std::vector<int> residentParts() const;  // the parts on the device now, by index
  std::vector<PartRange> ranges() const;
  size_t budgetBytes() const;       // what the parts may hold (the budget less the fixed bytes)
  size_t partBytesLargest() const;  // the largest part's stored slices
  double openMs() const;            // the streamed pass and the coarse level's upload

 private:
  void draw(const RenderParams& params, Image& out, OutOfCoreStats* stats, bool converge);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voxray
