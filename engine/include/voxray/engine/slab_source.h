#pragma once
// Where an out-of-core frame's slices come from (out_of_core.h, issue 38 part 2): a volume in
// memory, or one level of an OME-Zarr pyramid read a range of slices at a time, so that the
// host never holds the whole volume when it cannot. Each source also gives a coarse level with
// the full volume's box, shown where the device does not hold the full slices.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "voxray/io/volume.h"

namespace voxray {
struct RawLayout;
}

namespace voxray {

class SlabSource {
 public:
  virtual ~SlabSource() = default;
  // The volume without voxels: dims, spacing, origin, direction, slope, intercept, unit,
  // modality, window.
  virtual const Volume& geometry() const = 0;
  // Slices [FIRST, END) as stored values, i fastest, into DEST (dims.x * dims.y * (END -
  // FIRST) values). Throws Error (Input) when they cannot be read.
  virtual void readSlices(int first, int end, int16_t* dest) = 0;
  // Slices from FIRST where they already lie in host memory for as long as the source lives (a
  // CPU device then reads them in place), else nullptr.
  virtual const int16_t* slicesInPlace(int first) const {
    (void)first;
    return nullptr;
  }
  // The whole volume when it lies in host memory (the empty-space cells are then made from it
  // in place, without the streamed pass's copies), else nullptr.
  virtual const Volume* whole() const { return nullptr; }
  // Slices a read is best aligned to (a Zarr chunk's depth: a read across a chunk decodes it
  // whole); 0: any.
  virtual int preferredSlices() const { return 0; }
  // The volume's smallest and largest stored value when the source knows them without a pass
  // over the voxels: an OME-Zarr Voxray wrote states them, a raw file's source found them
  // making its coarse level. Else none (the renderer starts from the coarse level's). A hint:
  // the renderer checks it against the voxels as it reads them (out_of_core.h).
  virtual std::optional<ValueRange> statedRange() const { return std::nullopt; }
  // Chunks read so far that were missing, shown as empty (their fill value); 0 for sources
  // without chunks.
  virtual size_t missingChunks() const { return 0; }
  // A coarse level with the full volume's box (coarse_level.h's geometry), made or read once
  // and held by the source.
  virtual const Volume& coarse() = 0;
  // Where coarse() takes long (a raw file's 4x mean reads all of it; an OME-Zarr's coarse
  // level is 16 MiB to decode and march for the 8 GiB CT): a smaller level to show first, with
  // the full volume's box and value mapping (a raw file's: point samples; a Zarr's: a coarser
  // level of its pyramid). nullptr where coarse() is quick enough (the default). Made once
  // and held.
  virtual const Volume* quickLevel() { return nullptr; }
  // The dims coarse() has, without making it (the renderer plans its budget with them).
  virtual glm::ivec3 coarseDims() { return coarse().dims; }
  // Starts making coarse() on a thread of the source's own, once (where quickLevel() is not
  // nullptr; a no-op elsewhere). coarse() then waits for it; the source's destructor stops it.
  virtual void startCoarse() {}
  // coarse() is made (or failed: coarse() then throws), so that it returns at once.
  virtual bool coarseReady() const { return true; }
  // What the source is, for messages and the bench ("in memory", "OME-Zarr level 0").
  virtual std::string describe() const = 0;
};

// VOLUME (which must outlive the source), its coarse level the box mean of FACTOR (4 or 8).
std::unique_ptr<SlabSource> volumeSlabSource(const Volume& volume, int coarseFactor = 4);

// The raw INPUT (a file, a slice folder or pattern) under LAYOUT, read a range of slices at a
// time with pread, never whole (RawSliceReader: values stored as importRaw stores them). The
// coarse level, the 4x box mean, and the value range come from one streamed pass over the
// file (on the source's thread after startCoarse(), else when coarse() is asked for); until it
// ends, quickLevel() is shown: point samples every 2^n-th voxel (n >= 2) along each axis, at
// most kQuickVoxels of them. Throws Error (Input) as importRaw does.
std::unique_ptr<SlabSource> rawSlabSource(const std::string& input, const RawLayout& layout);
// The quick level's largest voxel count: 2 MiB of int16. Its read is what the first image
// waits for (the 8 GiB CT: 64 slices x 128 rows of 4 KiB), and a preview marches it.
constexpr size_t kQuickVoxels = size_t(1) << 20;

#ifdef VOXRAY_HAS_ZARR
// Level 0 of the OME-Zarr at PATH, read on demand; its coarse level the pyramid's first level
// whose voxels are at most 1/64 of level 0's and at most 32 MiB (the coarsest when none is), else
// the box mean of level 0 made while streaming. Its quick level the first level after that with
// at most kQuickVoxels, when there is one (the coarse level then read on the source's thread).
// Opening reads the metadata and the quick (else the coarse) level only. Throws Error (Input) as
// OmeZarrLevel does.
std::unique_ptr<SlabSource> omeZarrSlabSource(const std::string& path);
#endif

}  // namespace voxray
