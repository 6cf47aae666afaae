// Issue 34's goal: the STL of a bone segment of a 512x512x400 CT, smoothing and simplification
// to <= 500k triangles included, in <= 3 s on 2 cores. The Visible Human pelvis (150 slices of
// 512x512) is stacked back and forth to 400 slices and thresholded at 200 HU.
// Usage: voxray_mesh_bench [runs=3] [--save-mask FILE | --mask FILE]
// --save-mask writes the bone label map (512x512x400 bytes) for voxray_mesh_bench_mask, the
// same program without the DICOM reader, to run on another machine (--mask FILE).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef VOXRAY_MESH_BENCH_MASK_ONLY
#include "voxray/io/load.h"
#endif
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
  const std::string option = argc > 3 ? argv[2] : "", maskFile = argc > 3 ? argv[3] : "";
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("voxray-mesh-bench-" + std::to_string(getpid()) + ".stl"))
                              .string();
  Segmentation s;
  s.grid.dims = {512, 512, 400};
  s.labels.resize(s.grid.voxelCount());
  if (option == "--mask") {
    std::ifstream in(maskFile, std::ios::binary);
    in.read(reinterpret_cast<char*>(s.labels.data()), std::streamsize(s.labels.size()));
    if (!in) throw std::runtime_error("cannot read " + maskFile);
  } else {
#ifdef VOXRAY_MESH_BENCH_MASK_ONLY
    throw std::runtime_error("this build needs --mask FILE");
#else
    const Volume ct = loadVolume(VOXRAY_DATA_DIR "/dicom/ct-visible-human-pelvis");
    s.grid = gridOf(ct);
    s.grid.dims.z = 400;
    const size_t slice = size_t(ct.dims.x) * size_t(ct.dims.y);
    const int16_t boneStored =
        int16_t(std::lround((200.0 - ct.intercept) / ct.slope));  // 200 HU as stored
    for (int z = 0; z < 400; ++z) {
      const int period = 2 * ct.dims.z, k = z % period,
                src = k < ct.dims.z ? k : period - 1 - k;  // back and forth
      for (size_t i = 0; i < slice; ++i)
        s.labels[size_t(z) * slice + i] = ct.voxels[size_t(src) * slice + i] >= boneStored ? 1 : 0;
    }
    if (option == "--save-mask")
      std::ofstream(maskFile, std::ios::binary)
          .write(reinterpret_cast<const char*>(s.labels.data()), std::streamsize(s.labels.size()));
#endif
  }
  const size_t bone = size_t(std::count(s.labels.begin(), s.labels.end(), uint8_t(1)));
  s.segments.push_back(Segment{});
  s.segments.back().name = "Bone";
  std::printf("CT %dx%dx%d, spacing %.3f %.3f %.3f mm, bone (>= 200 HU) %zu voxels\n",
              s.grid.dims.x, s.grid.dims.y, s.grid.dims.z, s.grid.spacingMm.x, s.grid.spacingMm.y,
              s.grid.spacingMm.z, bone);

  std::vector<SurfaceTimings> timings;
  std::vector<double> surface, file;
  SegmentSurface last;
  for (int r = 0; r < runs; ++r) {
    SurfaceTimings t;
    auto start = Clock::now();
    last = makeSurface(s, 1, {}, &t);
    surface.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    timings.push_back(t);
    MeshFileOptions o;
    o.overwrite = true;
    start = Clock::now();
    writeMeshFile(out, s, {1}, o);  // the whole export: surface again + STL
    file.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  const EdgeCount e = countEdges(last);
  std::printf("flying edges gave %zu triangles\nmedians of %d runs, wall s (CPU s, all threads):\n",
              timings[0].extractedTriangles, runs);
  const auto stage = [&](const char* name, SurfaceTimings::Stage SurfaceTimings::*m) {
    std::vector<double> wall, cpu;
    for (const auto& t : timings) wall.push_back((t.*m).wall), cpu.push_back((t.*m).cpu);
    std::printf("  %-13s %6.3f (%6.3f)\n", name, median(wall), median(cpu));
  };
  stage("crop", &SurfaceTimings::crop);
  stage("flying edges", &SurfaceTimings::extract);
  stage("simplify", &SurfaceTimings::decimate);
  {
    std::vector<double> longest, sum;
    for (const auto& t : timings) longest.push_back(t.slabCpuMax), sum.push_back(t.slabCpuSum);
    std::printf("    of which meshoptimizer in slabs: longest slab %.3f, all slabs %.3f CPU s\n",
                median(longest), median(sum));
  }
  stage("smooth", &SurfaceTimings::smooth);
  stage("finish", &SurfaceTimings::finish);
  std::printf("  surface       %6.3f\n  whole STL export (surface + file) %6.3f\n", median(surface),
              median(file));
  std::printf(
      "triangles %zu, vertices %zu, area %.0f mm2, volume %.0f mm3; edges %zu: boundary %zu, "
      "non-manifold %zu, misoriented %zu -> %s\n",
      last.triangleCount(), last.vertices.size(), last.areaMm2, last.volumeMm3, e.edges, e.boundary,
      e.nonManifold, e.misoriented, e.closedManifold() ? "closed manifold" : "NOT closed manifold");
  for (const char* extension : {".obj", ".ply"}) {  // the other formats, once each
    const std::string other = out.substr(0, out.size() - 4) + extension;
    MeshFileOptions o;
    o.overwrite = true;
    const auto start = Clock::now();
    writeMeshFile(other, s, {1}, o);
    std::printf("whole %s export (1 run) %.3f s, %ju bytes\n", extension,
                std::chrono::duration<double>(Clock::now() - start).count(),
                std::uintmax_t(std::filesystem::file_size(other)));
    std::filesystem::remove(other);
    if (std::string(extension) == ".obj")
      std::filesystem::remove(out.substr(0, out.size() - 4) + ".mtl");
  }
  {  // the edges of flying edges' own output, to tell its defects from the simplifier's
    SurfaceOptions raw;
    raw.targetTriangles = 0;
    raw.smoothingIterations = 0;
    const EdgeCount r = countEdges(makeSurface(s, 1, raw));
    std::printf("flying edges alone: edges %zu: boundary %zu, non-manifold %zu, misoriented %zu\n",
                r.edges, r.boundary, r.nonManifold, r.misoriented);
  }
  std::printf("STL: %ju bytes\n", std::uintmax_t(std::filesystem::file_size(out)));
  std::ifstream load("/proc/loadavg");
  std::string l;
  std::getline(load, l);
  std::printf("loadavg %s (2 cores shared by six helpers)\n", l.c_str());
  std::filesystem::remove(out);
}
