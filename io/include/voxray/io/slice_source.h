#pragma once
// A volume read a range of slices at a time, for writers that must not hold it whole
// (voxray-cli convert, issue 38): a volume already in memory, a raw file or slice stack read
// with pread (RawSliceReader), or one level of an OME-Zarr (ome_zarr.h). The engine's
// SlabSource (out-of-core rendering) is the renderer's own, with coarse levels besides.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "voxray/io/raw_import.h"
#include "voxray/io/volume.h"

namespace voxray {

class SliceSource {
 public:
  virtual ~SliceSource() = default;
  // The volume without voxels: dims, spacing, origin, direction, slope and intercept (physical
  // = stored * slope + intercept), unit, modality, the warnings known on opening.
  virtual const Volume& geometry() const = 0;
  // Slices [FIRST, END) as stored values, i fastest, into DEST (dims.x * dims.y * (END - FIRST)
  // values). Throws Error (Input) when they cannot be read.
  virtual void readSlices(int first, int end, int16_t* dest) = 0;
  // Slices from FIRST where they already lie in memory for as long as the source lives (read
  // there without a copy), else nullptr.
  virtual const int16_t* slicesInPlace(int first) const {
    (void)first;
    return nullptr;
  }
  // The stored values' smallest and largest when the source knows them without another pass
  // over the voxels (a volume in memory; a raw input whose opening scanned every value), else
  // none: a writer that needs them reads the slices once more.
  virtual std::optional<ValueRange> storedRange() const { return std::nullopt; }
  // What the user should know after every slice was read: the opening's warnings and what the
  // reads found (missing chunks).
  virtual std::vector<std::string> warnings() const { return geometry().warnings; }
};

// VOLUME, which must outlive the source, read in place.
std::unique_ptr<SliceSource> volumeSliceSource(const Volume& volume);

// The raw INPUT (a file, a slice folder or a printf pattern) under LAYOUT read with pread a
// range of slices at a time: RawSliceReader, values and geometry as importRaw makes them.
// Throws Error (Input) as importRaw does.
std::unique_ptr<SliceSource> rawSliceSource(const std::string& input, const RawLayout& layout);

}  // namespace voxray
