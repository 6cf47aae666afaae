#pragma once
// What the raw-import dialog shows before loading: the size the layout expects against the
// size on disk, and one slice read straight from the file(s) with an automatic window.
#include <cstdint>
#include <optional>
#include <string>

#include "no_qt.h"
#include "voxray/io/image.h"
#include "voxray/io/raw_import.h"

namespace voxray::ui {

struct RawSizeCheck {
  uint64_t expectedBytes = 0;  // per file for a folder, else for the whole file
  uint64_t actualBytes = 0;    // of the first (or only) file
  int files = 0;               // slice files in a folder, 1 for a single file
  bool matches() const { return files > 0 && expectedBytes == actualBytes; }
};

// PATH: a single raw file or a folder of slice files. Never throws; files = 0 when unreadable.
RawSizeCheck checkRawSize(const std::string& path, const RawLayout& layout);

// The middle slice, grey with min..max of the slice mapped to black..white; nullopt when
// the file is too short for the layout.
std::optional<Image> previewRawSlice(const std::string& path, const RawLayout& layout);

}  // namespace voxray::ui
