// The ITK operations through the ITK module (libvoxray_itk.so; itk_module.h says why ITK is
// a module), loaded on the first one. Without the module each throws the loader's message,
// which names the file and the target to build; the rest of Voxray works.
#include <dlfcn.h>

#include "../../src/module/program_module.h"
#include "itk_module.h"
#include "segment_itk.h"
#include "voxray/io/error.h"

namespace voxray::itk_ops {
namespace {

struct ItkModule {
  decltype(&voxray_itk_run) run = nullptr;
  std::string missing;  // empty when loaded
};

const ItkModule& itkModule() {
  static const ItkModule m = [] {
    ItkModule loaded;
    const char* symbols[] = {"voxray_itk_run", nullptr};
    if (void* handle =
            loadProgramModule("libvoxray_itk.so", "ITK", "voxray_itk", symbols, &loaded.missing))
      loaded.run = reinterpret_cast<decltype(loaded.run)>(dlsym(handle, "voxray_itk_run"));
    return loaded;
  }();  // once, thread-safe
  return m;
}

void run(const char* what, int operation, Block& b, glm::ivec3 radius, bool full,
         Islands* islands) {
  const ItkModule& m = itkModule();
  if (!m.run) throw inputError(std::string(what) + " is unavailable (" + m.missing + ")");
  const int r[3] = {radius.x, radius.y, radius.z};
  std::string why;
  if (m.run(operation, &b, r, full ? 1 : 0, islands, &why) != 0)
    throw inputError(std::string(what) + " failed in ITK (" + why +
                     "): free memory, or segment a smaller region");
}

}  // namespace

Islands islands(const Block& b, bool fullyConnected) {
  Islands out;
  // Islands only reads the block: the module's one entry point takes it non-const.
  run("Keeping or removing islands", kVoxrayItkIslands, const_cast<Block&>(b), glm::ivec3(0),
      fullyConnected, &out);
  return out;
}
void median(Block& b, glm::ivec3 radius) {
  run("Median smoothing", kVoxrayItkMedian, b, radius, false, nullptr);
}
void closing(Block& b, glm::ivec3 radius) {
  run("Closing", kVoxrayItkClosing, b, radius, false, nullptr);
}
void opening(Block& b, glm::ivec3 radius) {
  run("Opening", kVoxrayItkOpening, b, radius, false, nullptr);
}
void fillHoles(Block& b) {
  run("ITK's fill holes", kVoxrayItkFillHoles, b, glm::ivec3(0), false, nullptr);
}

}  // namespace voxray::itk_ops
