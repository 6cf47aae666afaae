#pragma once
// What the raw-import dialog shows before loading: the size the layout expects against the
// size on disk, and one slice read straight from the file(s) with an automatic window,
// its value range and the patient letters its edges face.
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
  uint64_t sliceBytes = 0;     // one slice of the layout, header excluded
  int files = 0;               // slice files in a folder, 1 for a single file
  int filesWanted = 0;         // folder: the layout's slice count (0: every file)
  bool matches() const {
    return files > 0 && expectedBytes == actualBytes && (filesWanted == 0 || filesWanted == files);
  }
};

// PATH: a single raw file or a folder of slice files, by the importer's rules (a file with
// Z = 0 must hold a whole number of slices). Never throws; files = 0 when unreadable.
RawSizeCheck checkRawSize(const std::string& path, const RawLayout& layout);

// "" when C matches; else by how many bytes (and slices, or files) the input is off.
std::string sizeMismatchText(const RawSizeCheck& c);

struct RawPreview {
  Image image;            // the middle slice, lo..hi mapped to black..white
  double lo = 0, hi = 0;  // its stored values, before the layout's rescale
};

// The middle slice; nullopt when the file is too short for the layout.
std::optional<RawPreview> previewRawSlice(const std::string& path, const RawLayout& layout);

// The preview's value range after the layout's rescale, and a hint when it cannot be HU
// (air at about -1000): raw files carry no unit, and the rescale field is easy to miss.
std::string valueRangeText(const RawPreview& p, const RawLayout& layout);

// Patient letters for the preview's edges (x grows to the right, y downwards) and the
// direction slices advance in, from the layout's axes: LPI gives R, L, A, P and I.
struct EdgeLetters {
  char left = '?', right = '?', top = '?', bottom = '?', slices = '?';
};
EdgeLetters edgeLetters(const glm::dmat3& direction);

}  // namespace voxray::ui
