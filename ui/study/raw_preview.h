#pragma once
// What the raw-import dialog shows before loading, besides io's size check (raw_check.h):
// one slice read straight from the file(s) with an automatic window, its value range and
// the patient letters its edges face.
#include <cstdint>
#include <optional>
#include <string>

#include "no_qt.h"
#include "voxray/io/image.h"
#include "voxray/io/raw_check.h"
#include "voxray/io/raw_import.h"

namespace voxray {

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

}  // namespace voxray
