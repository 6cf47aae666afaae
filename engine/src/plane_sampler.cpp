#include "voxray/engine/plane_sampler.h"

#include "reference_sampling.h"
#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

std::vector<float> samplePlane(const Volume& v, const PlaneGrid& g, Interp interp,
                               float background) {
  const glm::ivec2 size = glm::max(g.size, glm::ivec2(0));
  std::vector<float> out(size_t(size.x) * size_t(size.y), background);
  if (v.voxelCount() == 0 || out.empty()) return out;
  // The grid is affine in voxel space too: one origin and two steps, no matrix per pixel.
  const glm::dmat3 patientToVoxel = glm::inverse(
      v.direction * glm::dmat3(glm::dvec3(v.spacingMm.x, 0, 0), glm::dvec3(0, v.spacingMm.y, 0),
                               glm::dvec3(0, 0, v.spacingMm.z)));
  const glm::dvec3 origin = patientToVoxel * (g.originMm - v.originMm);
  const glm::dvec3 stepX = patientToVoxel * (g.uDir * g.spacingMm.x);
  const glm::dvec3 stepY = patientToVoxel * (g.vDir * g.spacingMm.y);
  const glm::dvec3 lo(-0.5), hi = glm::dvec3(v.dims) - 0.5;
  parallelFor(size_t(size.y), [&](size_t row) {
    float* line = out.data() + row * size_t(size.x);
    const glm::dvec3 start = origin + double(row) * stepY;
    for (int x = 0; x < size.x; ++x) {
      const glm::dvec3 p = start + double(x) * stepX;
      if (glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi)))
        line[x] = float(v.toPhysical(sampleVolume(v, interp, p)));
    }
  });
  return out;
}

}  // namespace voxray
