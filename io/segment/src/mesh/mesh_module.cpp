// The mesh module's entry points (mesh_module.h): makeSurface and writeMeshFile with their
// errors caught here, so that none crosses into the program.
#include "mesh_module.h"

#include <exception>
#include <new>

#include "voxray/io/error.h"

namespace {

// Runs WORK; an error becomes *KIND and *WHY (1), success 0.
template <class Work>
int guarded(Work work, int* kind, std::string* why) {
  try {
    work();
    return 0;
  } catch (const voxray::Error& e) {
    *kind = int(e.kind());
    *why = e.what();
  } catch (const std::bad_alloc&) {
    *kind = int(voxray::Error::Kind::Input);
    *why = "not enough memory for the surface: free memory or mesh fewer segments";
  } catch (const std::exception& e) {
    *kind = int(voxray::Error::Kind::Internal);
    *why = e.what();
  }
  return 1;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int voxray_mesh_surface(
    const voxray::Segmentation* s, uint8_t label, const voxray::SurfaceOptions* options,
    voxray::SurfaceTimings* timings, voxray::SegmentSurface* out, int* kind, std::string* why) {
  return guarded([&] { *out = voxray::makeSurface(*s, label, *options, timings); }, kind, why);
}

__attribute__((visibility("default"))) int voxray_mesh_write(const char* path,
                                                             const voxray::Segmentation* s,
                                                             const std::vector<uint8_t>* labels,
                                                             const voxray::MeshFileOptions* options,
                                                             int* kind, std::string* why) {
  return guarded([&] { voxray::writeMeshFile(path, *s, *labels, *options); }, kind, why);
}
}
