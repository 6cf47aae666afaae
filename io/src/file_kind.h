#pragma once
// What kind of thing a path names, checked before any reader opens it: a FIFO, socket or
// device would block a reader forever or never end.
#include <string>

namespace voxray::detail {

// Throws Error (Input) when PATH exists but is neither a regular file nor a folder
// (symbolic links are followed). Does nothing for a missing path: callers say "no such".
void refuseSpecialFile(const std::string& path);

}  // namespace voxray::detail
