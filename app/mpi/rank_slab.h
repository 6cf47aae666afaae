#pragma once
// One rank's share of the volume (voxray-mpi): the z slices of its part and their apron.
// Raw inputs (a slice folder, a pattern, one raw file) are read slice by slice, so a rank
// reads only its slab from disk. The other readers (DICOM, NIfTI, NRRD, MetaImage, OME-Zarr,
// the phantom) have no slab read here: every rank reads the whole volume and keeps it.
#include <optional>
#include <string>

#include "voxray/engine/multi_device.h"
#include "voxray/io/load.h"

namespace voxray::mpi {

// True when INPUT is read as raw slices, which readSlab can read in part.
bool hasSlabRead(const std::string& input, const LoadOptions& options);

// The slices of a raw INPUT along z, from its listing and sizes alone (nothing is read).
int rawSlices(const std::string& input, const LoadOptions& options);

// Slices [range.storedFirst, range.storedEnd) of a raw INPUT, as a volume of their own.
Volume readSlab(const std::string& input, const LoadOptions& options, const PartRange& range);

// The whole volume's geometry (TOTALSLICES slices; origin at slice 0) from SLAB (readSlab's of
// RANGE), without voxels: what a rank renders its slab in (MultiDeviceOptions::slab).
Volume slabGeometry(const Volume& slab, const PartRange& range, int totalSlices);

// SLAB (readSlab's) placed in a volume of TOTALSLICES slices with the whole volume's geometry;
// the slices outside the range are FILL (the whole volume's smallest stored value, so that
// the empty-space grid's cells there stay empty and a cell across the edge keeps the slab's
// largest value). The part renderer reads none of them: its samples and their stencils lie in
// the stored range. Holds the whole volume's size in host memory: voxray-mpi renders from the
// slab and slabGeometry instead; this is the reference its tests place slices by.
Volume placeSlab(Volume slab, const PartRange& range, int totalSlices, int16_t fill);

}  // namespace voxray::mpi
