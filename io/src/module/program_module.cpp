#include "program_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace voxray {

void* loadProgramModule(const char* fileName, const char* what, const char* target,
                        const char* const* symbols, std::string* missing) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::string reasons;
  for (const fs::path& folder : {exe.parent_path(), exe.parent_path() / ".." / "lib" / "voxray"}) {
    const fs::path module = folder / fileName;
    void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      reasons += std::string(reasons.empty() ? "" : "; ") + (why ? why : module.string());
      continue;
    }
    bool complete = true;
    for (const char* const* s = symbols; *s && complete; ++s) complete = dlsym(handle, *s);
    if (complete) return handle;
    reasons += std::string(reasons.empty() ? "" : "; ") + module.string() + " lacks its functions";
  }
  if (missing)
    *missing = std::string(what) + "'s module " + fileName +
               " is not beside the program nor in ../lib/voxray (" + reasons +
               "): reinstall Voxray or rebuild it (target " + target + ")";
  return nullptr;
}

}  // namespace voxray
