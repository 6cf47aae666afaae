#pragma once
// computeMacroCells (macro_cells.h) of a SlabSource's volume without holding it: the slices are
// read GROUP (a multiple of kCellSize) at a time (streamed_cells.cpp).
#include "macro_cells.h"
#include "voxray/engine/slab_source.h"

namespace voxray {

MacroCells streamMacroCells(SlabSource& source, int group);

// computeMacroCells of a volume of TOTALSLICES slices whose slices [FIRST, FIRST +
// slab.dims.z) are SLAB's and the others FILL (at most every value of SLAB: an MPI rank's
// filler), holding SLAB and a few filler slices only (multi_device.cpp).
MacroCells slabMacroCells(const Volume& slab, int first, int totalSlices, int16_t fill);

}  // namespace voxray
