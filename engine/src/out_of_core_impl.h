#pragma once
// OutOfCoreRenderer's state (out_of_core.h), shared by its files: out_of_core.cpp (the plan, the
// frames), out_of_core_upload.cpp (a part to the device, pinned or direct) and
// out_of_core_rows.cpp (the empty-space rows and the value range learned from the slices read).
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "device_frame.h"
#include "elapsed_ms.h"
#include "empty_space.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/out_of_core.h"

namespace voxray {
namespace ooc {

using Clock = std::chrono::steady_clock;

}  // namespace ooc

struct OutOfCoreRenderer::Impl {
  struct Part {
    PartRange range;
    size_t bytes = 0;
    bool resident = false;
    cl::Buffer buffer;
    cl::Image3D image;
    cl::Event ready;    // its pinned copy, which its first launch after it waits for
    cl::Event lastUse;  // its last launch: its memory is free once that is done
  };
  // One pinned staging buffer of the ring: mapped once, its pointer the copies' source.
  struct Slot {
    cl::Buffer host;
    int16_t* ptr = nullptr;
    cl::Event copied;  // the last copy from it: its bytes are free to overwrite once done
  };
  // An evicted part's device memory (the pinned path), kept for the next part of its size.
  struct Spare {
    cl::Buffer buffer;
    cl::Image3D image;
    size_t bytes = 0;
    cl::Event lastUse;  // the evicted part's last launch: a copy into it waits for that
  };
  // One kernel launch of a frame: a part at full resolution, or slices [first, end) from the
  // coarse level.
  struct Item {
    int first = 0, end = 0;
    int part = -1;  // -1: coarse
    double key = 0.0;
  };

  ContextImpl& cl;
  SlabSource& src;
  OutOfCoreOptions o;
  const Volume& geom;
  // The coarse level on the device: the source's, or its quick level (point samples) until
  // that is made (slab_source.h): then QUICK, and the stats say "preview".
  const Volume* coarse;
  bool quick = false;
  VolumeStorage storage;
  DeviceFrame full;
  std::unique_ptr<DeviceFrame> coarseFrame;  // made again for the level that replaces it
  EmptySpace fullSpace, coarseSpace;
  cl::Buffer coarseBuffer;
  cl::Image3D coarseImage;
  std::vector<Part> parts;
  size_t partBudget = 0, residentBytes = 0, fixedBytes = 0;
  int uploadsDone = 0;
  bool evictedPending = false;  // a part left the device since the queue last finished
  double openMs = 0.0;
  cl::Buffer colour, order;  // one launch's image on the device
  cl::Buffer accBuffer;      // the composite so far, on the device (float4 per pixel)
  size_t capacity = 0;
  std::vector<float> acc;  // the composite, read back once the frame's parts are in
  // One part's slices on their way to the device, kept for the next: freeing and allocating
  // a part's bytes per upload let glibc's raised mmap threshold put them on the heap, whose
  // fragments the process kept (peak RSS 0.36-0.65x of a streamed Zarr in tests/cli).
  std::vector<int16_t> staging;
  // The pinned path (OutOfCoreOptions::Upload): made at its first upload.
  bool pinned = false;
  std::vector<Slot> ring;
  size_t ringNext = 0;
  cl::CommandQueue transfer;       // in order, profiling on; the copies alone
  std::vector<cl::Event> freeing;  // the last launches on the parts evicted since the last copy
  std::vector<Spare> spares;       // evicted, not yet reused or released
  Spare takeSpare(size_t bytes);   // one of BYTES (none: empty); the others released
  // This frame's launches and copies not yet counted, and what those counted took. An event
  // holds its command and so the buffers it used (PoCL frees an evicted part's memory only
  // with its last launch's event): they are counted and dropped as they finish.
  std::vector<cl::Event> kernelEvents, copyEvents;
  double kernelMs = 0.0, copyMs = 0.0;
  void harvest();
  // The cell rows along z made from the voxels so far (out_of_core.h), those not yet applied,
  // the values they hold, and the range the source stated or the coarse level's.
  std::vector<char> rowKnown;
  int rowsKnown = 0;
  std::vector<std::pair<glm::ivec2, std::vector<int16_t>>> pendingRows;
  int knownLo = INT16_MAX, knownHi = INT16_MIN;
  ValueRange hint{};
  bool hintStated = false;
  ValueRange used{};  // what the frames' tables span now
  std::string note;

  Impl(ContextImpl& c, SlabSource& s, const OutOfCoreOptions& opts, VolumeStorage st,
       const Volume* quickLevel)
      : cl(c),
        src(s),
        o(opts),
        geom(s.geometry()),
        coarse(quickLevel ? quickLevel : &s.coarse()),
        quick(quickLevel != nullptr),
        storage(st),
        full(c, geom, st),
        coarseFrame(std::make_unique<DeviceFrame>(c, *coarse, st)) {
    pinned = o.upload == OutOfCoreOptions::Upload::Pinned ||
             (o.upload == OutOfCoreOptions::Upload::Auto && c.info.isGpu);
  }
  ~Impl() {
    try {
      for (Slot& slot : ring)
        if (slot.ptr) transfer.enqueueUnmapMemObject(slot.host, slot.ptr);
      if (transfer()) transfer.finish();
      cl.queue.finish();
    } catch (const cl::Error&) {
      // the buffers go with the context; nothing else to do while tearing down
    }
  }

  size_t sliceBytes() const { return size_t(geom.dims.x) * size_t(geom.dims.y) * 2; }
  void upload(Part& part, OutOfCoreStats& s);
  void uploadPinned(Part& part, OutOfCoreStats& s);
  bool makeRing();
  void evict(Part& part) {
    if (!ring.empty() && o.reuseDeviceMemory)
      spares.push_back({part.buffer, part.image, part.bytes, part.lastUse});
    else if (part.lastUse())
      freeing.push_back(part.lastUse);
    part.buffer = cl::Buffer();
    part.image = cl::Image3D();
    part.resident = false;
    residentBytes -= part.bytes;
    evictedPending = true;
    part.lastUse = cl::Event();
    part.ready = cl::Event();
  }
  // The coarse level (and its cells) to the device; Error (Device) when it cannot go.
  void uploadCoarse();
  // The quick level replaced by the source's coarse level (made, or waited for), its range
  // taken as stated once the pass that found it is done.
  void replaceQuick();
  // A streamed source's cells, all conservative (out_of_core.h), made at the first frame that
  // draws a part: until then CELLSPENDING.
  void makeConservativeCells();
  bool cellsPending = false;
  void learnRows(const int16_t* slices, int first, int end);
  ValueRange currentRange() const;
  bool applyLearned();
  void keys(std::vector<Item>& items, const RenderParams& p);
  void launch(const Item& item, const RenderParams& p);
  void setUp(DeviceFrame& f, EmptySpace& space, const RenderParams& p, RaycastParams& k,
             std::string& options, bool classify = true);
};

}  // namespace voxray
