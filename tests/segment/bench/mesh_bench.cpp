// Issue 34's goal: the STL of a bone segment of a 512x512x400 CT, smoothing and simplification
// to <= 500k triangles included, in <= 3 s on 2 cores. The Visible Human pelvis (150 slices of
// 512x512) is stacked back and forth to 400 slices and thresholded at 200 HU.
// Usage: voxray_mesh_bench [runs=3] [out.stl (default: a temporary file, removed)]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "voxray/io/load.h"
#include "voxray/io/mesh_file.h"
#include "voxray/io/segment_mesh.h"

using namespace voxray;
using Clock = std::chrono::steady_clock;

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::stoi(argv[1]) : 3;
  const std::string out = argc > 2 ? argv[2]
                                   : (std::filesystem::temp_directory_path() /
                                      ("voxray-mesh-bench-" + std::to_string(getpid()) + ".stl"))
                                         .string();
  const Volume ct = loadVolume(VOXRAY_DATA_DIR "/dicom/ct-visible-human-pelvis");
  Segmentation s;
  s.grid = gridOf(ct);
  s.grid.dims.z = 400;
  s.labels.resize(s.grid.voxelCount());
  const size_t slice = size_t(ct.dims.x) * size_t(ct.dims.y);
  size_t bone = 0;
  const int16_t boneStored =
      int16_t(std::lround((200.0 - ct.intercept) / ct.slope));  // 200 HU as stored
  for (int z = 0; z < 400; ++z) {
    const int period = 2 * ct.dims.z, k = z % period,
              src = k < ct.dims.z ? k : period - 1 - k;  // back and forth
    for (size_t i = 0; i < slice; ++i)
      bone += s.labels[size_t(z) * slice + i] =
          ct.voxels[size_t(src) * slice + i] >= boneStored ? 1 : 0;
  }
  s.segments.push_back(Segment{});
  s.segments.back().name = "Bone";
  std::printf("CT %dx%dx%d, spacing %.3f %.3f %.3f mm, bone (>= 200 HU) %zu voxels\n",
              s.grid.dims.x, s.grid.dims.y, s.grid.dims.z, s.grid.spacingMm.x, s.grid.spacingMm.y,
              s.grid.spacingMm.z, bone);

  std::vector<double> crop, extract, decimate, smooth, finish, surface, file;
  SegmentSurface last;
  for (int r = 0; r < runs; ++r) {
    SurfaceTimings t;
    auto start = Clock::now();
    last = makeSurface(s, 1, {}, &t);
    surface.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    crop.push_back(t.crop), extract.push_back(t.extract), decimate.push_back(t.decimate);
    smooth.push_back(t.smooth), finish.push_back(t.finish);
    MeshFileOptions o;
    o.overwrite = true;
    start = Clock::now();
    writeMeshFile(out, s, {1}, o);  // the whole export: surface again + STL
    file.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  const EdgeCount e = countEdges(last);
  std::printf(
      "medians of %d runs (s): crop %.3f, flying edges %.3f, simplify %.3f, smooth %.3f, finish "
      "%.3f; "
      "surface %.3f; whole STL export %.3f\n",
      runs, median(crop), median(extract), median(decimate), median(smooth), median(finish),
      median(surface), median(file));
  std::printf(
      "triangles %zu, vertices %zu, area %.0f mm2, volume %.0f mm3; edges %zu: boundary %zu, "
      "non-manifold %zu, misoriented %zu -> %s\n",
      last.triangleCount(), last.vertices.size(), last.areaMm2, last.volumeMm3, e.edges, e.boundary,
      e.nonManifold, e.misoriented, e.closedManifold() ? "closed manifold" : "NOT closed manifold");
  std::printf("STL %s: %ju bytes\n", out.c_str(), std::uintmax_t(std::filesystem::file_size(out)));
  std::ifstream load("/proc/loadavg");
  std::string l;
  std::getline(load, l);
  std::printf("loadavg %s (2 cores shared by six helpers)\n", l.c_str());
  if (argc <= 2) std::filesystem::remove(out);
}
