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
// The slices come from a SlabSource (slab_source.h), read per part and released after upload.
// Opening reads no full-resolution slice (the first image must not wait for 8 GiB, issue 38):
// the empty-space cells of parts not yet read are conservative (min -32768, max 32767: every
// transfer function finds them occupied, so skipping stays exact) and are filled in from each
// part's slices when it is first read (the cell rows all of whose voxels it holds), applied at
// the next frame. The value range, which the colour table spans (its entries lie between the
// range's ends) and which a mip without a window maps to grey, starts as the source states it
// (voxray-cli convert writes it into the Zarr) or else as the coarse level's, widened to the
// cells read; once every row is read it is the voxels' own, as in core. A converged frame
// whose range changed while it read its parts is drawn again with the range it ended with, so
// a converged frame is the in-core frame (within the bound above) from the first one on. A
// stated range the voxels contradict is replaced and the stats say so. An in-memory source's
// cells and range are made from it in place when the renderer is made.
//
// A source whose coarse level is slow to make or read (slab_source.h's quickLevel: a raw file's
// 4x mean is a pass over the whole file) is first shown from its quick level, a smaller one; the
// first preview starts the coarse level on the source's thread, and the first frame after it is
// made draws from it. A converged frame waits for it (its pass finds the value range, so the
// frame is drawn once). The plan's budget counts the coarse level's bytes either way: the
// parts, and so the converged frames, do not depend on which level is shown.
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
  // Pinned: an evicted part's device memory is kept for the next part of the same size, its
  // copy waiting on the device for the evicted part's last launch. NVIDIA's runtime waited for
  // a buffer's queued launches when it was released, which ran the read, the copy and the
  // kernels one after another. False (benchmarks' A/B): released and allocated as Direct does.
  bool reuseDeviceMemory = true;
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
  int allocations = 0;  // device allocations for parts in this frame (fewer than uploads: reused)
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
  // The converged frame was drawn twice: its value range grew as its parts were first read.
  bool redrawnForRange = false;
  double cellsKnown = 1.0;   // of the empty-space cell rows, those made from the voxels
  size_t missingChunks = 0;  // the source's chunks read so far that were missing (drawn empty)
  std::string note;          // about the data, for the user (missing chunks, a wrong range)
  // What the frame shows: "full" (every part at full resolution), "coarse" (parts from the
  // coarse level, the box mean) or "preview" (parts from the source's quick level, point
  // samples, before the coarse level is made: slab_source.h).
  std::string shown = "full";
};

class OutOfCoreRenderer {
 public:
  // CONTEXT and SOURCE must outlive the renderer. Reads the source's coarse level (and an
  // in-memory source's cells) and uploads it; no full-resolution slice. Throws Error (Input) when
  // the budget cannot hold one part (naming the budget, the bytes one part needs and the budget to
  // ask for), and Error (Device) when the coarse level cannot be uploaded.
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

  // Builds the programs a frame of P needs (the parts' and the coarse level's raycast, the
  // composite, the cells' classification) on CONTEXT, as ClContext::prebuild does: a thread
  // runs it while the renderer is made, so the first image waits for the compiler less (a
  // build with an empty PoCL cache takes seconds). Throws Error (Device) with the build log.
  static void prebuild(ClContext& context, const RenderParams& p,
                       const OutOfCoreOptions& options = {});

  int partCount() const;
  int residentCount() const;
  std::vector<int> residentParts() const;  // the parts on the device now, by index
  std::vector<PartRange> ranges() const;
  size_t budgetBytes() const;       // what the parts may hold (the budget less the fixed bytes)
  size_t partBytesLargest() const;  // the largest part's stored slices
  double openMs() const;            // the coarse level's read and upload

 private:
  void draw(const RenderParams& params, Image& out, OutOfCoreStats* stats, bool converge);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voxray
