#include "slice_image.h"

#include "time_series.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "value_look.h"
#include "voxray/engine/measure.h"
#include "voxray/io/volume.h"

namespace voxray {

PlaneGrid slicePlane(const Volume& v, const SliceAxes& a, double slice) {
  const glm::dvec2 extentMm(v.dims[a.uAxis] * v.spacingMm[a.uAxis],
                            v.dims[a.vAxis] * v.spacingMm[a.vAxis]);
  // Square pixels of the finer spacing: a 5 mm axis gets several pixels per voxel to
  // interpolate, rather than a stretched voxel-sized block.
  const double pixelMm = std::max({std::min(v.spacingMm[a.uAxis], v.spacingMm[a.vAxis]),
                                   extentMm.x / kMaxSlicePixels, extentMm.y / kMaxSlicePixels});
  PlaneGrid g;
  g.size = glm::max(glm::ivec2(glm::round(extentMm / pixelMm)), glm::ivec2(1));
  // Pixel centres in slice coordinates (voxel units), mapped like any view position.
  const glm::dvec2 voxelsPerPixel =
      glm::dvec2(v.dims[a.uAxis], v.dims[a.vAxis]) / glm::dvec2(g.size);
  auto at = [&](double x, double y) {
    return voxelToPatientMm(
        v, sliceToVoxel(a, v.dims, x * voxelsPerPixel.x, y * voxelsPerPixel.y, slice));
  };
  g.originMm = at(0.5, 0.5);
  const glm::dvec3 u = at(1.5, 0.5) - g.originMm, w = at(0.5, 1.5) - g.originMm;
  g.spacingMm = {glm::length(u), glm::length(w)};
  g.uDir = u / g.spacingMm.x;
  g.vDir = w / g.spacingMm.y;
  return g;
}

PlaneGrid viewPlane(const Volume& v, const SliceAxes& a, const glm::dvec3& centreVoxel,
                    const glm::dmat3& rotation) {
  PlaneGrid g = slicePlane(v, a, centreVoxel[a.nAxis]);
  if (rotation == glm::dmat3(1.0)) return g;
  const glm::dvec3 centre = voxelToPatientMm(v, centreVoxel);
  g.originMm = centre + rotation * (g.originMm - centre);
  g.uDir = rotation * g.uDir;
  g.vDir = rotation * g.vDir;
  return g;
}

Image renderSlice(const Volume& v, const SliceAxes& a, int slice, const WindowLevel& wl,
                  Interp interp) {
  if (v.voxelCount() == 0) return {};
  return renderPlane(v, slicePlane(v, a, std::clamp(slice, 0, v.dims[a.nAxis] - 1)), wl, interp);
}

Image renderPlane(const Volume& v, const PlaneGrid& g, const WindowLevel& wl, Interp interp,
                  const Slab& slab) {
  if (v.voxelCount() == 0) return {};
  // The lowest value maps to black: outside the volume (an oblique plane's corners).
  const std::vector<float> values =
      samplePlane(v, g, interp, std::numeric_limits<float>::lowest(), slab);
  Image img(g.size.x, g.size.y);
  for (int y = 0; y < g.size.y; ++y)
    for (int x = 0; x < g.size.x; ++x) {
      uint8_t grey = mapToGrey(values[size_t(y) * size_t(g.size.x) + size_t(x)], wl);
      uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = grey;
      p[3] = 255;
    }
  return img;
}

double sampleValue(const Volume& v, const glm::dvec3& voxel) {
  glm::ivec3 i(glm::round(voxel));
  if (glm::any(glm::lessThan(i, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(i, v.dims)))
    return std::numeric_limits<double>::quiet_NaN();
  return v.toPhysical(v.at(i.x, i.y, i.z));
}

}  // namespace voxray

namespace voxray {

CursorProbe probeAt(const Volume& v, const glm::dvec3& voxel, Interp interp) {
  CursorProbe p;
  p.unit = readoutUnit(v);  // HU only for values that are HU; SUVbw for a PET with its scale
  p.voxel = glm::ivec3(glm::round(voxel));
  const glm::dvec3 at = interp == Interp::Nearest ? glm::dvec3(p.voxel) : voxel;
  p.patientMm = voxelToPatient(v, at);
  p.inside = v.voxelCount() > 0 && insideVolume(v, at);
  if (!p.inside) return p;
  // A one-pixel plane through the point: the very sampler the slice image uses.
  PlaneGrid g;
  g.originMm = p.patientMm;
  g.size = {1, 1};
  p.value = readoutValue(v, samplePlane(v, g, interp, 0.0F).front());
  p.decimals = v.suv ? 3 : 0;  // SUVs are small numbers: 6.607, not 7
  return p;
}

}  // namespace voxray
