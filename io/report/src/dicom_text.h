#pragma once
// What the SR and KOS writers share: new UIDs, today's date, the atomic save.
#include <string>

class DcmFileFormat;

namespace voxray::report {

std::string newUid(const char* root);
std::string now(const char* format);  // strftime of the local time
// Saves FILE into PATH aside then renamed, so an interrupted write leaves no half file.
// WHAT names the object in the error message.
void saveAtomically(DcmFileFormat& file, const std::string& path, const std::string& what);

}  // namespace voxray::report
