#pragma once
// Modules Voxray's programs load on first use instead of linking (libvoxray_oiio.so,
// libvoxray_mp4.so): their libraries' relocations and static constructors were most of every
// voxray-cli start for commands that never use them (issue 39 item 8).
#include <string>

namespace voxray {

// The module FILE_NAME (e.g. "libvoxray_mp4.so") beside the program (the build tree's bin/),
// else where it is installed (../lib/voxray), loaded once; SYMBOLS (null-terminated list)
// must all be in it. Returns its handle for dlsym, or null with *MISSING set to what a user
// reads: "WHAT's module FILE_NAME is not beside the program nor in ../lib/voxray (REASONS):
// reinstall Voxray or rebuild it (target TARGET)".
void* loadProgramModule(const char* fileName, const char* what, const char* target,
                        const char* const* symbols, std::string* missing);

}  // namespace voxray
