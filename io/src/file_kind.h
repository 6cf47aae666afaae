#pragma once
// What kind of thing a path names, checked before any reader opens it: a FIFO, socket or
// device would block a reader forever or never end; a file that a header or DICOMDIR names
// must stay beside it (a hostile one names /etc/shadow, or a link to it).
#include <string>

namespace voxray::detail {

// Throws Error (Input) when PATH exists but is neither a regular file nor a folder
// (symbolic links are followed). Does nothing for a missing path: callers say "no such".
void refuseSpecialFile(const std::string& path);

// Where a file named by another file (a detached data file, a DICOMDIR entry) lies.
enum class Placement { Inside, Missing, Outside, NotRegular };

// CANDIDATE (absolute, or relative to the working folder) with every symbolic link resolved,
// against FOLDER (its links resolved too): Inside when it is a regular file in FOLDER or below
// it. RESOLVED, when given, receives the resolved path.
Placement placeInFolder(const std::string& folder, const std::string& candidate,
                        std::string* resolved = nullptr);

}  // namespace voxray::detail
