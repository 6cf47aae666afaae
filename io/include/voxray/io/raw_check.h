#pragma once
// Checks a raw input against a layout before anything is loaded, by the importer's own
// rules: what the raw-import dialog shows while the user types, and the slice it previews.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "voxray/io/raw_import.h"

namespace voxray {

struct RawSizeCheck {
  uint64_t expectedBytes = 0;  // per file for a folder, else for the whole file
  uint64_t actualBytes = 0;    // of the deciding file: the first of a folder whose size is off
  uint64_t sliceBytes = 0;     // one slice of the layout, header excluded
  std::string file;            // name of the deciding file (without its folder)
  int files = 0;               // slice files in a folder, 1 for a single file, 0: unreadable
  int filesWanted = 0;         // folder: the layout's slice count (0: every file)
  std::string problem;         // why the input cannot be listed at all (files = 0)
  bool matches() const {
    return files > 0 && expectedBytes == actualBytes && (filesWanted == 0 || filesWanted == files);
  }
};

// INPUT: a single raw file, a folder of numbered slice files or a pattern such as
// slices/%03d.tif (limited to layout.range; a pattern without one: every file it names).
// Never throws.
RawSizeCheck checkRawSize(const std::string& input, const RawLayout& layout);

// "" when C matches; else by how many bytes (and slices, or files) the input is off.
std::string sizeMismatchText(const RawSizeCheck& c);

// The middle slice of INPUT as raw sample values (before the layout's rescale), x fastest;
// nullopt when the input is too short for the layout or cannot be read.
std::optional<std::vector<double>> readMiddleRawSlice(const std::string& input,
                                                      const RawLayout& layout);

}  // namespace voxray
