// The parts of the mesh interface that need no VTK (file names, formats, edge counts): in
// voxray_segment itself and in the mesh module (mesh_module.h), which writes the files.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "voxray/io/error.h"
#include "voxray/io/mesh_file.h"
#include "voxray/io/segment_mesh.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

MeshFormat meshFormatFor(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  throw inputError("Cannot tell the mesh format of \"" + path +
                   "\": end the name with .stl, .obj or .ply.");
}

std::string perSegmentPath(const std::string& path, const Segment& segment) {
  const fs::path p(path);
  std::string name;
  for (char c : segment.name) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')
      name += c;
    else if (!name.empty() && name.back() != '_')
      name += '_';
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  std::string file = p.stem().string() + "_" + std::to_string(segment.label);
  if (!name.empty()) {
    file += '_';
    file.append(name, 0, 64);
  }
  return (p.parent_path() / (file + p.extension().string())).string();
}

EdgeCount countEdges(const SegmentSurface& surface) {
  // Each directed edge as (min, max) << 1 | direction, sorted: equal keys then sit together.
  std::vector<uint64_t> keys;
  keys.reserve(surface.indices.size());
  for (size_t i = 0; i + 2 < surface.indices.size(); i += 3)
    for (int e = 0; e < 3; ++e) {
      const uint64_t a = surface.indices[i + e], b = surface.indices[i + (e + 1) % 3];
      keys.push_back((std::min(a, b) << 33) | (std::max(a, b) << 1) | (a < b ? 1 : 0));
    }
  std::sort(keys.begin(), keys.end());
  EdgeCount c;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i, forward = 0;
    while (j < keys.size() && (keys[j] >> 1) == (keys[i] >> 1)) forward += keys[j++] & 1;
    const size_t n = j - i;
    ++c.edges;
    if (n == 1) ++c.boundary;
    if (n > 2) ++c.nonManifold;
    if (n == 2 && forward != 1) ++c.misoriented;
    i = j;
  }
  return c;
}

}  // namespace voxray
