#pragma once
// A label map as text for the session file: zlib-compressed (a label map is long runs of a
// few values: a 512x512x400 map of a skull is some hundreds of kB), then base64.
#include <cstdint>
#include <string>
#include <vector>

namespace voxray {

std::string labelMapToText(const std::vector<uint8_t>& labels);
// Throws an input Error naming FIELD when the text is not base64 of zlib data or does not
// hold exactly `voxels` labels.
std::vector<uint8_t> labelMapFromText(const std::string& text, size_t voxels,
                                      const std::string& field);

}  // namespace voxray
