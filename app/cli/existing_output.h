#pragma once
// The rule of every command that writes a file: an existing file is kept unless the user said
// to replace it. Checked before the work, so a long run does not end in the refusal.
#include <string>

namespace voxray::cli {

// Throws an Output error "PATH exists: give FLAG to replace it, or another name." when PATH
// exists and REPLACE is false; an empty PATH (no such output asked for) passes.
void refuseExisting(const std::string& path, bool replace, const char* flag = "--force");

}  // namespace voxray::cli
