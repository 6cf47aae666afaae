#pragma once
// computeMacroCells (macro_cells.h) of a SlabSource's volume without holding it: the slices are
// read GROUP (a multiple of kCellSize) at a time (out_of_core.cpp).
#include "macro_cells.h"
#include "voxray/engine/slab_source.h"

namespace voxray {

MacroCells streamMacroCells(SlabSource& source, int group);

}  // namespace voxray
