#include "voxray/engine/plane_sampler.h"

#include <algorithm>
#include <cmath>

#include "reference_sampling.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// The grid is affine in voxel space too: one origin and two steps, no matrix per pixel.
struct VoxelPlane {
  glm::dmat3 patientToVoxel;
  glm::dvec3 origin, stepX, stepY;
  glm::dvec3 lo{-0.5}, hi;
  bool inside(const glm::dvec3& p) const {
    return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi));
  }
};

VoxelPlane voxelPlane(const Volume& v, const PlaneGrid& g) {
  VoxelPlane vg;
  vg.patientToVoxel = glm::inverse(v.direction * glm::dmat3(glm::dvec3(v.spacingMm.x, 0, 0),
                                                            glm::dvec3(0, v.spacingMm.y, 0),
                                                            glm::dvec3(0, 0, v.spacingMm.z)));
  vg.origin = vg.patientToVoxel * (g.originMm - v.originMm);
  vg.stepX = vg.patientToVoxel * (g.uDir * g.spacingMm.x);
  vg.stepY = vg.patientToVoxel * (g.vDir * g.spacingMm.y);
  vg.hi = glm::dvec3(v.dims) - 0.5;
  return vg;
}

// Fills one value per pixel, rows in parallel: PIXEL(voxel position, &value) sets the value
// and returns true, or leaves it at BACKGROUND.
template <class Pixel>
std::vector<float> samplePixels(const Volume& v, const PlaneGrid& g, float background,
                                const VoxelPlane& vg, const Pixel& pixel) {
  const glm::ivec2 size = glm::max(g.size, glm::ivec2(0));
  std::vector<float> out(size_t(size.x) * size_t(size.y), background);
  if (v.voxelCount() == 0 || out.empty()) return out;
  parallelFor(size_t(size.y), [&](size_t row) {
    float* line = out.data() + row * size_t(size.x);
    const glm::dvec3 start = vg.origin + double(row) * vg.stepY;
    for (int x = 0; x < size.x; ++x) pixel(start + double(x) * vg.stepX, line[x]);
  });
  return out;
}

}  // namespace

std::vector<float> samplePlane(const Volume& v, const PlaneGrid& g, Interp interp,
                               float background) {
  const VoxelPlane vg = voxelPlane(v, g);
  return samplePixels(v, g, background, vg, [&](const glm::dvec3& p, float& value) {
    if (vg.inside(p)) value = float(v.toPhysical(sampleVolume(v, interp, p)));
  });
}

const char* toString(SlabMode m) {
  static const char* const kNames[] = {"mip", "minip", "mean"};  // SlabMode's order
  return kNames[size_t(m)];
}

SlabMode parseSlabMode(const std::string& s) {
  for (SlabMode m : {SlabMode::Mip, SlabMode::MinIp, SlabMode::Mean})
    if (s == toString(m)) return m;
  throw inputError("slab mode '" + s + "' is not one of mip, minip, mean");
}

int slabSamples(const Volume& v, const Slab& slab) {
  if (!(slab.thicknessMm > 0.0)) return 1;  // NaN too: a thin plane
  const double step = v.minSpacingMm();
  // Bounded: a slab thicker than any volume still costs a few thousand samples at most.
  const double n = std::ceil(slab.thicknessMm / step) + 1.0;
  return int(std::clamp(n, 2.0, 4096.0));
}

std::vector<float> samplePlane(const Volume& v, const PlaneGrid& g, Interp interp, float background,
                               const Slab& slab) {
  const int n = slabSamples(v, slab);
  if (n == 1) return samplePlane(v, g, interp, background);
  const VoxelPlane vg = voxelPlane(v, g);
  // Offsets across the slab in voxel units, from face to face.
  const glm::dvec3 normal = glm::normalize(glm::cross(g.uDir, g.vDir));
  std::vector<glm::dvec3> offsets(size_t(n), glm::dvec3(0.0));
  for (int k = 0; k < n; ++k)
    offsets[size_t(k)] =
        vg.patientToVoxel * (normal * (slab.thicknessMm * (double(k) / double(n - 1) - 0.5)));
  return samplePixels(v, g, background, vg, [&](const glm::dvec3& p, float& value) {
    int count = 0;
    double acc = 0.0;
    for (const glm::dvec3& offset : offsets) {
      const glm::dvec3 at = p + offset;
      if (!vg.inside(at)) continue;
      const double s = v.toPhysical(sampleVolume(v, interp, at));  // a slope may be < 0
      acc = count == 0                     ? s
            : slab.mode == SlabMode::Mip   ? std::max(acc, s)
            : slab.mode == SlabMode::MinIp ? std::min(acc, s)
                                           : acc + s;
      ++count;
    }
    if (count == 0) return;
    if (slab.mode == SlabMode::Mean) acc /= count;
    value = float(acc);
  });
}

}  // namespace voxray
