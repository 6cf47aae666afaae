#include "rank_slab.h"

#include <algorithm>

#include "voxray/engine/coarse_level.h"  // withoutVoxels
#include "voxray/io/error.h"

namespace voxray::mpi {

bool hasSlabRead(const std::string& input, const LoadOptions& options) {
  return !input.empty() && options.raw.has_value();
}

int rawSlices(const std::string& input, const LoadOptions& options) {
  return rawSliceCount(input, *options.raw);
}

Volume readSlab(const std::string& input, const LoadOptions& options, const PartRange& range) {
  RawLayout layout = *options.raw;
  layout.zSlab = std::pair<int, int>{range.storedFirst, range.storedEnd};
  return importRaw(input, layout, {options.progress, options.cancel});
}

Volume slabGeometry(const Volume& slab, const PartRange& range, int totalSlices) {
  Volume v = withoutVoxels(slab);
  v.study = slab.study;
  v.warnings = slab.warnings;
  v.dims.z = totalSlices;
  // readSlab's origin is at its first slice: back to slice 0.
  v.originMm -= v.direction * glm::dvec3(0.0, 0.0, range.storedFirst * v.spacingMm.z);
  return v;
}

Volume placeSlab(Volume slab, const PartRange& range, int totalSlices, int16_t fill) {
  const int held = range.storedEnd - range.storedFirst;
  if (slab.dims.z != held)
    throw inputError("the slab holds " + std::to_string(slab.dims.z) + " slices, not the " +
                     std::to_string(held) + " of slices " + std::to_string(range.storedFirst) +
                     " to " + std::to_string(range.storedEnd - 1));
  VoxelVector slices = std::move(slab.voxels);
  Volume v = std::move(slab);
  v.dims.z = totalSlices;
  // readSlab's origin is at its first slice: back to slice 0 (as slabGeometry).
  v.originMm -= v.direction * glm::dvec3(0.0, 0.0, range.storedFirst * v.spacingMm.z);
  const size_t sliceVoxels = size_t(v.dims.x) * size_t(v.dims.y);
  v.voxels.assign(v.voxelCount(), fill);
  std::copy(slices.begin(), slices.end(),
            v.voxels.begin() + std::ptrdiff_t(size_t(range.storedFirst) * sliceVoxels));
  return v;
}

}  // namespace voxray::mpi
