// Builds without ITK's operations (a compiler other than GCC: ITK 5.2's headers do not build
// with it, or no ITK): each says so, naming the build to use.
#include "segment_itk.h"
#include "voxray/io/error.h"

namespace voxray::itk_ops {
namespace {

[[noreturn]] void unavailable(const char* what) {
  throw Error(Error::Kind::Input, std::string(what) +
                                      " is unavailable in this build (it needs ITK, which "
                                      "builds with GCC only): use a GCC build of Voxray.");
}

}  // namespace

Islands islands(const Block&, bool) { unavailable("Keeping or removing islands"); }
void median(Block&, glm::ivec3) { unavailable("Median smoothing"); }
void closing(Block&, glm::ivec3) { unavailable("Closing"); }
void opening(Block&, glm::ivec3) { unavailable("Opening"); }
void fillHoles(Block&) { unavailable("ITK's fill holes"); }

}  // namespace voxray::itk_ops
