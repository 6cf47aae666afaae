#pragma once
// Error messages from io and engine are written for voxray-cli and name its flags
// ("check --raw-dims"). The workstation shows them with the names of its own controls
// instead; the CLI's wording stays as it is. The raw-import dialog labels its fields from
// the same table, so a message and the field it points to always agree.
#include <string>

#include "no_qt.h"

namespace voxray {

// The workstation's name for the input flag KEY (inputFlagSpecs' key, without "--"): the
// raw-import dialog's field label, e.g. "Dimensions x, y, z" for raw-dims. Throws Error
// (Input) for a key without one.
const std::string& inputFieldLabel(const std::string& key);

// MESSAGE with each input flag ("--raw-dims", with an upper-case value hint after it such
// as "X,Y,Z") replaced by its field label in quotes.
std::string guiMessage(const std::string& message);

}  // namespace voxray
