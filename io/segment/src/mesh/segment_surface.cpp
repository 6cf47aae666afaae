#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <mutex>
#include <string>
#include <thread>
#include <tuple>

#include <meshoptimizer.h>
#include <vtkCellArray.h>
#include <vtkDecimatePro.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/segment_mesh.h"
#include "voxray/io/segmentation_check.h"

namespace voxray {
namespace {

using Clock = std::chrono::steady_clock;
double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Start {
  Clock::time_point wall = Clock::now();
  std::clock_t cpu = std::clock();  // every thread of the process
};
SurfaceTimings::Stage since(const Start& s) {
  return {std::chrono::duration<double>(Clock::now() - s.wall).count(),
          double(std::clock() - s.cpu) / CLOCKS_PER_SEC};
}

struct Box {
  glm::ivec3 lo{INT32_MAX}, hi{-1};
  size_t voxels = 0;
};

// The voxels' bounding box, one slice per task (a 512x512x400 scan takes ~40 ms on 2 cores).
Box labelBox(const Segmentation& s, uint8_t label) {
  const glm::ivec3 d = s.grid.dims;
  std::vector<Box> slices(size_t(d.z));
  parallelFor(size_t(d.z), [&](size_t z) {
    Box b;
    const uint8_t* slice = s.labels.data() + size_t(z) * size_t(d.x) * size_t(d.y);
    for (int y = 0; y < d.y; ++y) {
      const uint8_t* row = slice + size_t(y) * size_t(d.x);
      int first = -1, last = -1;
      size_t n = 0;
      for (int x = 0; x < d.x; ++x)
        if (row[x] == label) {
          if (first < 0) first = x;
          last = x;
          ++n;
        }
      if (n == 0) continue;
      b.voxels += n;
      b.lo = glm::min(b.lo, glm::ivec3(first, y, int(z)));
      b.hi = glm::max(b.hi, glm::ivec3(last, y, int(z)));
    }
    slices[z] = b;
  });
  Box all;
  for (const auto& b : slices)
    if (b.voxels) {
      all.voxels += b.voxels;
      all.lo = glm::min(all.lo, b.lo);
      all.hi = glm::max(all.hi, b.hi);
    }
  return all;
}

// The segment as 0/1 over its box with one empty voxel all round, so that the surface closes.
// Points come out in "grid millimetres" (index x spacing, before origin and direction).
vtkSmartPointer<vtkImageData> binaryCrop(const Segmentation& s, uint8_t label, const Box& box) {
  const glm::ivec3 n = box.hi - box.lo + 3;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n.x, n.y, n.z);
  image->SetSpacing(s.grid.spacingMm.x, s.grid.spacingMm.y, s.grid.spacingMm.z);
  const glm::dvec3 origin = glm::dvec3(box.lo - 1) * s.grid.spacingMm;
  image->SetOrigin(origin.x, origin.y, origin.z);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* out = static_cast<uint8_t*>(image->GetScalarPointer());
  std::memset(out, 0, size_t(n.x) * size_t(n.y) * size_t(n.z));
  parallelFor(size_t(n.z - 2), [&](size_t k) {
    const int z = box.lo.z + int(k);
    for (int y = box.lo.y; y <= box.hi.y; ++y) {
      const uint8_t* in = s.labels.data() + s.grid.index(box.lo.x, y, z);
      uint8_t* o = out + ((k + 1) * size_t(n.y) + size_t(y - box.lo.y + 1)) * size_t(n.x) + 1;
      for (int x = 0; x <= box.hi.x - box.lo.x; ++x) o[x] = in[x] == label ? 1 : 0;
    }
  });
  return image;
}

struct Mesh {
  std::vector<float> xyz;  // 3 per vertex
  std::vector<uint32_t> indices;
};

Mesh meshOf(vtkPolyData* poly) {
  Mesh m;
  const vtkIdType nPoints = poly->GetNumberOfPoints();
  m.xyz.resize(size_t(nPoints) * 3);
  for (vtkIdType i = 0; i < nPoints; ++i) {
    double p[3];
    poly->GetPoint(i, p);
    m.xyz[size_t(i) * 3 + 0] = float(p[0]);
    m.xyz[size_t(i) * 3 + 1] = float(p[1]);
    m.xyz[size_t(i) * 3 + 2] = float(p[2]);
  }
  vtkCellArray* polys = poly->GetPolys();
  // Flying edges, the decimators and the smoother give triangles only.
  if (polys->IsStorage64Bit()) {
    auto* c = polys->GetConnectivityArray64();
    m.indices.assign(c->GetPointer(0), c->GetPointer(0) + c->GetNumberOfValues());
  } else {
    auto* c = polys->GetConnectivityArray32();
    m.indices.assign(c->GetPointer(0), c->GetPointer(0) + c->GetNumberOfValues());
  }
  if (m.indices.size() != size_t(polys->GetNumberOfCells()) * 3)
    throw Error(Error::Kind::Internal, "Surface mesh: a polygon that is not a triangle");
  return m;
}

vtkSmartPointer<vtkPolyData> polyOfMesh(const Mesh& m) {
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(vtkIdType(m.xyz.size() / 3));
  std::copy(m.xyz.begin(), m.xyz.end(), xyz->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkNew<vtkTypeInt32Array> connectivity, offsets;
  connectivity->SetNumberOfValues(vtkIdType(m.indices.size()));
  std::copy(m.indices.begin(), m.indices.end(), connectivity->GetPointer(0));
  const vtkIdType triangles = vtkIdType(m.indices.size() / 3);
  offsets->SetNumberOfValues(triangles + 1);
  for (vtkIdType t = 0; t <= triangles; ++t) offsets->SetValue(t, int32_t(3 * t));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

// meshoptimizer's edge collapse: seconds for a bone of millions of triangles where VTK's
// quadric and DecimatePro took 35-99 s (measured on a 512x512x400 CT). Error bound 1 (the
// mesh's whole extent): it stops at the triangle count, not at an error.
std::vector<uint32_t> simplifyPart(const std::vector<float>& xyz,
                                   const std::vector<uint32_t>& indices, size_t target,
                                   unsigned options) {
  std::vector<uint32_t> out(indices.size());
  out.resize(meshopt_simplify(out.data(), indices.data(), indices.size(), xyz.data(),
                              xyz.size() / 3, 3 * sizeof(float), target * 3, 1.0f, options));
  return out;
}

// Edge collapses can fold a thin part flat: two triangles on the same three vertices, back to
// back, whose edges then sit in four triangles. The pair encloses nothing; removing it leaves
// the surface around it closed.
size_t removeFolds(Mesh& m) {
  struct Key {
    uint32_t v[3];
    bool flipped;
    size_t triangle;
  };
  std::vector<Key> keys(m.indices.size() / 3);
  for (size_t t = 0; t < keys.size(); ++t) {
    uint32_t a = m.indices[3 * t], b = m.indices[3 * t + 1], c = m.indices[3 * t + 2];
    // Rotate the smallest first; then the order of the other two is the winding.
    if (b < a && b < c)
      std::tie(a, b, c) = std::make_tuple(b, c, a);
    else if (c < a && c < b)
      std::tie(a, b, c) = std::make_tuple(c, a, b);
    const bool flipped = c < b;
    keys[t] = {{a, flipped ? c : b, flipped ? b : c}, flipped, t};
  }
  const auto sameVertices = [](const Key& p, const Key& q) {
    return p.v[0] == q.v[0] && p.v[1] == q.v[1] && p.v[2] == q.v[2];
  };
  std::sort(keys.begin(), keys.end(), [](const Key& p, const Key& q) {
    return std::tie(p.v[0], p.v[1], p.v[2], p.flipped) <
           std::tie(q.v[0], q.v[1], q.v[2], q.flipped);
  });
  std::vector<char> drop(keys.size(), 0);
  size_t dropped = 0;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i, flipped = 0;
    while (j < keys.size() && sameVertices(keys[i], keys[j])) flipped += keys[j++].flipped;
    // As many of one winding as of the other cancel out: drop them all.
    if (j - i > 1 && 2 * flipped == j - i)
      for (size_t k = i; k < j; ++k) drop[keys[k].triangle] = 1, ++dropped;
    i = j;
  }
  if (!dropped) return 0;
  size_t out = 0;
  for (size_t t = 0; t < drop.size(); ++t)
    if (!drop[t])
      for (int c = 0; c < 3; ++c) m.indices[out++] = m.indices[3 * t + c];
  m.indices.resize(out);
  return dropped;
}

// The simplifier is serial; the mesh is cut into slabs of equal triangle counts along z, each
// simplified on its own core with the cut's vertices locked, so that the slabs still meet
// vertex for vertex; then welded by the vertices' original numbers.
void simplify(Mesh& m, size_t targetTriangles, SurfaceTimings& timings) {
  const size_t triangles = m.indices.size() / 3;
  const size_t slabs =
      std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), triangles / 100000 + 1);
  std::vector<uint32_t> kept;
  if (slabs <= 1) {
    const double cpu = threadCpuSeconds();
    kept = simplifyPart(m.xyz, m.indices, targetTriangles, 0);
    timings.slabCpuMax = timings.slabCpuSum = threadCpuSeconds() - cpu;
  } else {
    std::vector<float> zs(triangles);
    for (size_t t = 0; t < triangles; ++t)
      zs[t] = m.xyz[3 * m.indices[3 * t] + 2] + m.xyz[3 * m.indices[3 * t + 1] + 2] +
              m.xyz[3 * m.indices[3 * t + 2] + 2];
    std::vector<float> sorted = zs;
    std::vector<float> cuts;
    for (size_t k = 1; k < slabs; ++k) {
      std::nth_element(sorted.begin(), sorted.begin() + k * triangles / slabs, sorted.end());
      cuts.push_back(sorted[k * triangles / slabs]);
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<uint32_t> slabOf(triangles);
    for (size_t t = 0; t < triangles; ++t)
      slabOf[t] = uint32_t(std::upper_bound(cuts.begin(), cuts.end(), zs[t]) - cuts.begin());
    std::vector<std::vector<uint32_t>> results(slabs);
    std::vector<double> cpu(slabs);
    parallelFor(slabs, [&](size_t k) {
      const double cpuStart = threadCpuSeconds();
      std::vector<uint32_t> local(m.xyz.size() / 3, UINT32_MAX), global, indices;
      std::vector<float> xyz;
      for (size_t t = 0; t < triangles; ++t) {
        if (slabOf[t] != k) continue;
        for (int c = 0; c < 3; ++c) {
          const uint32_t g = m.indices[3 * t + c];
          if (local[g] == UINT32_MAX) {
            local[g] = uint32_t(global.size());
            global.push_back(g);
            xyz.insert(xyz.end(), m.xyz.begin() + 3 * g, m.xyz.begin() + 3 * g + 3);
          }
          indices.push_back(local[g]);
        }
      }
      const size_t target = targetTriangles * (indices.size() / 3) / triangles;
      std::vector<uint32_t> out = simplifyPart(xyz, indices, target, meshopt_SimplifyLockBorder);
      for (auto& i : out) i = global[i];
      results[k] = std::move(out);
      cpu[k] = threadCpuSeconds() - cpuStart;
    });
    timings.slabCpuMax = *std::max_element(cpu.begin(), cpu.end());
    for (double c : cpu) timings.slabCpuSum += c;
    for (const auto& r : results) kept.insert(kept.end(), r.begin(), r.end());
  }
  m.indices = std::move(kept);
  removeFolds(m);
  std::vector<float> xyz(m.xyz.size());
  const size_t vertices =
      meshopt_optimizeVertexFetch(xyz.data(), m.indices.data(), m.indices.size(), m.xyz.data(),
                                  m.xyz.size() / 3, 3 * sizeof(float));
  xyz.resize(vertices * 3);
  m.xyz = std::move(xyz);
}

vtkSmartPointer<vtkPolyData> decimateKeepingTopology(vtkPolyData* poly, size_t targetTriangles) {
  vtkNew<vtkDecimatePro> decimate;
  decimate->SetInputData(poly);
  decimate->SetTargetReduction(1.0 - double(targetTriangles) / double(poly->GetNumberOfPolys()));
  decimate->PreserveTopologyOn();
  decimate->SplittingOff();
  decimate->BoundaryVertexDeletionOff();
  decimate->Update();
  return decimate->GetOutput();
}

vtkSmartPointer<vtkPolyData> smooth(vtkPolyData* poly, const SurfaceOptions& o) {
  vtkNew<vtkWindowedSincPolyDataFilter> smoother;
  smoother->SetInputData(poly);
  smoother->SetNumberOfIterations(o.smoothingIterations);
  smoother->SetPassBand(o.passBand);
  // Normalised coordinates keep the pass band independent of the segment's size (as Slicer).
  smoother->NormalizeCoordinatesOn();
  smoother->BoundarySmoothingOff();
  smoother->FeatureEdgeSmoothingOff();
  smoother->NonManifoldSmoothingOn();
  smoother->Update();
  return smoother->GetOutput();
}

// VTK makes its object-factory list on the first New() and not thread-safely: segments meshed
// in parallel (mesh_file.cpp) made it twice at once, and LeakSanitizer found the lost copy. The
// first surface of the process makes it alone.
void initialiseVtkFactories() {
  static std::once_flag once;
  std::call_once(once, [] { vtkObjectFactory::GetRegisteredFactories(); });
}

}  // namespace

SegmentSurface makeSurface(const Segmentation& s, uint8_t label, const SurfaceOptions& options,
                           SurfaceTimings* timings) {
  initialiseVtkFactories();
  checkSegmentation(s);
  const Segment* segment = s.find(label);
  if (!segment)
    throw inputError("No segment has label " + std::to_string(label) +
                     ": choose one of the segmentation's segments.");
  if (options.smoothingIterations < 0 || options.passBand <= 0 || options.passBand > 2)
    throw inputError(
        "Surface smoothing: iterations must be >= 0 and the pass band in (0, 2]; got " +
        std::to_string(options.smoothingIterations) + " and " + std::to_string(options.passBand) +
        ".");
  SurfaceTimings t;
  Start start;
  const Box box = labelBox(s, label);
  if (box.voxels == 0)
    throw inputError(
        "Segment \"" + segment->name + "\" (label " + std::to_string(label) +
        ") has no voxels, so it has no surface: paint or threshold it first, or leave it out.");
  auto image = binaryCrop(s, label, box);
  t.crop = since(start);

  start = Start();
  vtkNew<vtkFlyingEdges3D> edges;
  edges->SetInputData(image);
  edges->SetValue(0,
                  0.5);  // halfway between outside (0) and inside (1): the voxels' faces' midpoints
  edges->ComputeNormalsOff();
  edges->ComputeGradientsOff();
  edges->ComputeScalarsOff();
  edges->Update();
  vtkSmartPointer<vtkPolyData> poly = edges->GetOutput();
  image = nullptr;
  t.extract = since(start);

  start = Start();
  const size_t triangles = size_t(poly->GetNumberOfPolys());
  t.extractedTriangles = triangles;
  // Simplify before smoothing (3D Slicer's order): the smoother then runs on the fewer
  // triangles, and smooths away the simplifier's staircase corners.
  const bool reduce = options.targetTriangles > 0 && triangles > options.targetTriangles;
  Mesh mesh;
  if (reduce && options.preserveTopology) {
    poly = decimateKeepingTopology(poly, options.targetTriangles);
  } else if (reduce) {
    mesh = meshOf(poly);
    simplify(mesh, options.targetTriangles, t);
    poly = options.smoothingIterations > 0 ? polyOfMesh(mesh) : nullptr;
  }
  t.decimate = since(start);

  start = Start();
  if (options.smoothingIterations > 0) poly = smooth(poly, options);
  t.smooth = since(start);

  start = Start();
  if (poly) mesh = meshOf(poly);
  SegmentSurface out;
  out.label = label;
  out.vertices.resize(mesh.xyz.size() / 3);
  const glm::dmat3 dir = s.grid.direction;
  const glm::dvec3 origin = s.grid.originMm;
  for (size_t i = 0; i < out.vertices.size(); ++i) {
    const glm::dvec3 p(mesh.xyz[3 * i], mesh.xyz[3 * i + 1], mesh.xyz[3 * i + 2]);
    out.vertices[i] = glm::vec3(origin + dir * p);
  }
  out.indices = std::move(mesh.indices);
  double area = 0, volume = 0;
  for (size_t i = 0; i + 2 < out.indices.size(); i += 3) {
    const glm::dvec3 a = out.vertices[out.indices[i]], b = out.vertices[out.indices[i + 1]],
                     c = out.vertices[out.indices[i + 2]];
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  // Flying edges' winding and a left-handed direction matrix decide which way the triangles
  // face; turn them outwards, where the enclosed volume is positive.
  if (volume < 0) {
    for (size_t i = 0; i + 2 < out.indices.size(); i += 3)
      std::swap(out.indices[i + 1], out.indices[i + 2]);
    volume = -volume;
  }
  out.areaMm2 = area;
  out.volumeMm3 = volume;
  t.finish = since(start);
  if (timings) *timings = t;
  return out;
}

}  // namespace voxray
