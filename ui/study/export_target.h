#pragma once
// Where an export goes, decided before any pixel is written: the default suffix, and never
// replacing an existing file without the user's yes. The file dialog's own question is not
// enough: it asks about the name as typed, before ".png" is appended.
#include <functional>
#include <optional>
#include <string>

#include "no_qt.h"

namespace voxray {

// PATH with ".png" appended when it has no extension (PNG, TIFF and EXR are told apart by it).
std::string withImageSuffix(const std::string& path);

// Asked with the final path when that file exists; true = replace it.
using ConfirmOverwrite = std::function<bool(const std::string& path)>;

// The path to write, or nullopt when nothing must be written (empty choice, or an existing
// file the user chose to keep). CONFIRM is called only for an existing file.
std::optional<std::string> resolveExportTarget(const std::string& chosen,
                                               const ConfirmOverwrite& confirm);

}  // namespace voxray
