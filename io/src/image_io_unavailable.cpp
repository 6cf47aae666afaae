// Image I/O for lean builds configured with VOXRAY_WITH_OIIO=OFF (benchmarks carried to
// machines that lack OpenImageIO's libraries): every call says how to get the real one.
#include "voxray/io/error.h"
#include "voxray/io/image.h"

namespace voxray {

void writeImage(const std::string& path, const Image&) {
  throw outputError(path +
                    ": this build writes no images (configured with "
                    "VOXRAY_WITH_OIIO=OFF); use a default build");
}

Image readImage(const std::string& path) {
  throw inputError(path +
                   ": this build reads no images (configured with "
                   "VOXRAY_WITH_OIIO=OFF); use a default build");
}

}  // namespace voxray
