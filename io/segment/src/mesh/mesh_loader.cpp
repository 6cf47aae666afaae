// makeSurface and writeMeshFile through the mesh module (libvoxray_mesh.so, mesh_module.h
// says why VTK is a module), loaded on the first call. Without the module both throw the
// loader's message, which names the file and the target to build; the rest of Voxray works.
#include <dlfcn.h>

#include "../../../src/module/program_module.h"
#include "mesh_module.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

struct MeshModule {
  decltype(&voxray_mesh_surface) surface = nullptr;
  decltype(&voxray_mesh_write) write = nullptr;
  std::string missing;  // empty when loaded
};

MeshModule loadModule() {
  MeshModule m;
  const char* symbols[] = {"voxray_mesh_surface", "voxray_mesh_write", nullptr};
  void* handle = loadProgramModule("libvoxray_mesh.so", "VTK", "voxray_mesh", symbols, &m.missing);
  if (!handle) return m;
  m.surface = reinterpret_cast<decltype(m.surface)>(dlsym(handle, "voxray_mesh_surface"));
  m.write = reinterpret_cast<decltype(m.write)>(dlsym(handle, "voxray_mesh_write"));
  return m;
}

const MeshModule& meshModule() {
  static const MeshModule m = loadModule();  // once, thread-safe
  return m;
}

[[noreturn]] void rethrow(int kind, const std::string& why) {
  throw Error(static_cast<Error::Kind>(kind), why);
}

}  // namespace

SegmentSurface makeSurface(const Segmentation& s, uint8_t label, const SurfaceOptions& options,
                           SurfaceTimings* timings) {
  const MeshModule& m = meshModule();
  if (!m.surface)
    throw outputError("Cannot make the surface of segment " + std::to_string(label) + " (" +
                      m.missing + ")");
  SegmentSurface out;
  int kind = 0;
  std::string why;
  if (m.surface(&s, label, &options, timings, &out, &kind, &why) != 0) rethrow(kind, why);
  return out;
}

void writeMeshFile(const std::string& path, const Segmentation& s,
                   const std::vector<uint8_t>& labels, const MeshFileOptions& options) {
  const MeshModule& m = meshModule();
  if (!m.write) throw outputError(path + ": cannot write surface meshes (" + m.missing + ")");
  int kind = 0;
  std::string why;
  if (m.write(path.c_str(), &s, &labels, &options, &kind, &why) != 0) rethrow(kind, why);
}

}  // namespace voxray
