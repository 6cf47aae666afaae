#pragma once
// The one rule for how many bytes a raw file must hold, used by the importer (which refuses
// a mismatch) and by checkRawSize (which the import dialog shows live).
#include <cstdint>

#include "voxray/io/raw_import.h"

namespace voxray::detail {

struct RawFileBytes {
  uint64_t sliceBytes = 0;  // one slice of the layout, header excluded
  uint64_t slices = 0;      // slices the file is read as
  uint64_t expected = 0;    // header + slices * sliceBytes
  // Z = 0 on a single file: the data after the header is not a whole number of slices
  // (or is empty); `slices` is then what it would hold, at least one.
  bool partialSlice = false;
};

// A slice file of a stack holds the header and one slice; a single raw file holds the header
// and Z slices, or with Z = 0 as many whole slices as it has (at least one). FOUND is the
// file's size in bytes.
RawFileBytes rawFileBytes(const RawLayout& layout, uint64_t found, bool stackSlice);

}  // namespace voxray::detail
