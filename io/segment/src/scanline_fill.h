#pragma once
// The seeded scanline flood fill of a 3D box: marks (visited = 1) every voxel connected to the
// seed through voxels where fillable(index) holds. Hand-written rather than ITK's
// ConnectedThresholdImageFilter: that one visits voxel by voxel through a neighbourhood
// iterator and a queue of indices (seconds on a 512x512x400 CT), where filling whole runs of
// a row at a time and only pushing the start of each run in the neighbouring rows takes
// about 0.3 s there (segment_bench).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace voxray {

template <class Fillable>
void scanlineFill(glm::ivec3 dims, glm::ivec3 seed, bool full26, std::vector<uint8_t>& visited,
                  Fillable&& fillable) {
  const size_t nx = size_t(dims.x), nxy = nx * size_t(dims.y);
  auto at = [&](int x, int y, int z) { return size_t(z) * nxy + size_t(y) * nx + size_t(x); };
  if (!fillable(at(seed.x, seed.y, seed.z))) return;
  std::vector<glm::ivec3> stack{seed};
  while (!stack.empty()) {
    const glm::ivec3 p = stack.back();
    stack.pop_back();
    const size_t row = at(0, p.y, p.z);
    if (visited[row + size_t(p.x)]) continue;
    int xl = p.x, xr = p.x;
    while (xl > 0 && !visited[row + size_t(xl - 1)] && fillable(row + size_t(xl - 1))) --xl;
    while (xr + 1 < dims.x && !visited[row + size_t(xr + 1)] && fillable(row + size_t(xr + 1)))
      ++xr;
    for (int x = xl; x <= xr; ++x) visited[row + size_t(x)] = 1;
    // The neighbouring rows: faces only (y +-1 or z +-1 over [xl, xr]) or, with 26, every row
    // of the 3x3 around, one voxel wider on each side (edges and corners).
    const int grow = full26 ? 1 : 0;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        if (dy == 0 && dz == 0) continue;
        if (!full26 && dy != 0 && dz != 0) continue;
        const int y = p.y + dy, z = p.z + dz;
        if (y < 0 || y >= dims.y || z < 0 || z >= dims.z) continue;
        const size_t r = at(0, y, z);
        const int from = std::max(xl - grow, 0), to = std::min(xr + grow, dims.x - 1);
        bool inRun = false;
        for (int x = from; x <= to; ++x) {
          const bool open = !visited[r + size_t(x)] && fillable(r + size_t(x));
          if (open && !inRun) stack.push_back({x, y, z});
          inRun = open;
        }
      }
    }
  }
}

}  // namespace voxray
