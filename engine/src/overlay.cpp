#include "voxray/engine/overlay.h"

#include <algorithm>
#include <cmath>

#include "macro_cells.h"
#include "overlay_cells.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// Voxel (centres at integers) -> patient LPS mm.
glm::dmat4 voxelToPatient(const Volume& v) {
  glm::dmat4 m(1.0);
  for (int a = 0; a < 3; ++a) m[a] = glm::dvec4(v.direction[a] * v.spacingMm[a], 0.0);
  m[3] = glm::dvec4(v.originMm, 1.0);
  return m;
}

struct ColourStop {
  double at;
  glm::dvec3 rgb;
};

std::vector<ColourStop> colourMap(const std::string& name) {
  if (name == "hot-iron")  // black through red and orange to white, as PET viewers show it
    return {{0.0, {0.0, 0.0, 0.0}},
            {0.35, {0.75, 0.05, 0.0}},
            {0.7, {1.0, 0.6, 0.0}},
            {1.0, {1.0, 1.0, 1.0}}};
  if (name == "rainbow")
    return {{0.0, {0.0, 0.0, 1.0}},
            {0.25, {0.0, 1.0, 1.0}},
            {0.5, {0.0, 1.0, 0.0}},
            {0.75, {1.0, 1.0, 0.0}},
            {1.0, {1.0, 0.0, 0.0}}};
  if (name == "grey") return {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 1.0, 1.0}}};
  throw inputError("--overlay-colormap: '" + name +
                   "' is not a colour map (hot-iron, rainbow, grey)");
}

}  // namespace

glm::dmat4 overlayVoxelMap(const Volume& base, const Volume& overlay) {
  return glm::inverse(voxelToPatient(overlay)) * voxelToPatient(base);
}

std::vector<std::string> overlayWarnings(const Volume& base, const Volume& overlay) {
  const std::string& a = base.study.frameOfReferenceUid;
  const std::string& b = overlay.study.frameOfReferenceUid;
  if (!a.empty() && a == b) return {};
  return {std::string("the overlay and the volume ") +
          (a.empty() || b.empty() ? "do not both name a Frame of Reference"
                                  : "name different Frames of Reference") +
          ": it is placed by its patient coordinates, which need not match the volume's; "
          "register the two (or check the fused picture) before trusting where it shows"};
}

void checkOverlayFits(size_t overlayBytes, size_t maxAllocBytes) {
  if (overlayBytes <= maxAllocBytes) return;
  throw deviceError("the overlay needs " + std::to_string(overlayBytes) +
                    " bytes in one allocation; the device allows " + std::to_string(maxAllocBytes) +
                    ": crop or downsample the overlay, or render on a device with more memory");
}

TransferFunction overlayWindowTable(double lo, double hi, const std::string& colormap,
                                    double opacity) {
  const std::vector<ColourStop> stops = colourMap(colormap);
  if (!(hi > lo))
    throw inputError("--overlay-window: LO must be below HI, got " + std::to_string(lo) + "," +
                     std::to_string(hi));
  opacity = std::clamp(opacity, 0.0, 1.0);
  TransferFunction tf;
  for (const ColourStop& s : stops)
    tf.points.push_back({lo + s.at * (hi - lo), glm::dvec4(s.rgb, opacity * s.at)});
  return tf;
}

TransferFunction scaledOpacity(TransferFunction tf, double factor) {
  for (ControlPoint& p : tf.points) p.rgba.a = std::clamp(p.rgba.a * factor, 0.0, 1.0);
  return tf;
}

OverlayClassifier::OverlayClassifier(const Volume& base, const Volume& o,
                                     const TransferFunction& tf)
    : overlay(&o), lut(bakeLut(tf, o)), map(overlayVoxelMap(base, o)) {}

bool OverlayClassifier::value(const glm::dvec3& pv, double& stored) const {
  const Volume& o = *overlay;
  const glm::dvec3 q(map * glm::dvec4(pv, 1.0));
  const glm::dvec3 d(o.dims);
  for (int a = 0; a < 3; ++a)
    if (q[a] < -0.5 || q[a] > d[a] - 0.5) return false;
  const glm::dvec3 f = glm::floor(q), w = q - f;
  const glm::ivec3 n = o.dims - 1;
  const glm::ivec3 i0 = glm::clamp(glm::ivec3(f), glm::ivec3(0), n);
  const glm::ivec3 i1 = glm::clamp(glm::ivec3(f) + 1, glm::ivec3(0), n);
  auto v = [&](int x, int y, int z) { return double(o.at(x, y, z)); };
  auto lx = [&](int y, int z) { return glm::mix(v(i0.x, y, z), v(i1.x, y, z), w.x); };
  stored = glm::mix(glm::mix(lx(i0.y, i0.z), lx(i1.y, i0.z), w.y),
                    glm::mix(lx(i0.y, i1.z), lx(i1.y, i1.z), w.y), w.z);
  return true;
}

glm::dvec4 OverlayClassifier::at(const glm::dvec3& pv) const {
  double s = 0.0;
  return value(pv, s) ? lut.lookup(s) : glm::dvec4(0.0);
}

double overlayMipOpacity(const Lut& lut) {
  float top = 0.0f;
  for (const glm::vec4& e : lut.rgba) top = std::max(top, e.a);
  return std::clamp(double(top), 0.0, 1.0);
}

glm::dvec3 OverlayClassifier::overMip(const glm::dvec3& grey, double largest) const {
  const glm::dvec4 c = lut.lookup(largest);
  if (!(c.a > 0.0)) return grey;
  return glm::mix(grey, glm::dvec3(c), overlayMipOpacity(lut));
}

std::vector<uint8_t> overlayCells(const Volume& base, const Volume& o, const Lut& lut,
                                  const glm::dmat4& map) {
  const glm::ivec3 cells = (base.dims + (kCellSize - 1)) / kCellSize;
  std::vector<uint8_t> out(size_t(cells.x) * size_t(cells.y) * size_t(cells.z), 0);
  std::vector<int> opaqueBefore(lut.rgba.size() + 1, 0);
  for (size_t i = 0; i < lut.rgba.size(); ++i)
    opaqueBefore[i + 1] = opaqueBefore[i] + (lut.rgba[i].a > 0.0f);
  if (opaqueBefore.back() == 0) return out;
  const int last = int(lut.rgba.size()) - 1;
  const glm::dvec3 d(o.dims);
  parallelFor(size_t(cells.z), [&](size_t cz) {
    for (int cy = 0; cy < cells.y; ++cy)
      for (int cx = 0; cx < cells.x; ++cx) {
        // Every sample in the cell lies within its span (macro_cells.h), a box in base voxels.
        const glm::dvec3 lo = glm::dvec3(kCellSize * glm::ivec3(cx, cy, int(cz)) - 1);
        const glm::dvec3 hi = lo + double(kCellSize + 1);
        glm::dvec3 qmin(1e300), qmax(-1e300);
        for (int k = 0; k < 8; ++k) {
          const glm::dvec3 p(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
          const glm::dvec3 q(map * glm::dvec4(p, 1.0));
          qmin = glm::min(qmin, q);
          qmax = glm::max(qmax, q);
        }
        if (glm::any(glm::lessThan(qmax, glm::dvec3(-0.5))) ||
            glm::any(glm::greaterThan(qmin, d - 0.5)))
          continue;  // the span misses the overlay's box: it is transparent there
        const glm::ivec3 a = glm::clamp(glm::ivec3(glm::floor(qmin)), glm::ivec3(0), o.dims - 1);
        const glm::ivec3 b =
            glm::clamp(glm::ivec3(glm::floor(qmax)) + 1, glm::ivec3(0), o.dims - 1);
        int16_t vmin = INT16_MAX, vmax = INT16_MIN;
        for (int z = a.z; z <= b.z; ++z)
          for (int y = a.y; y <= b.y; ++y)
            for (int x = a.x; x <= b.x; ++x) {
              const int16_t s = o.voxels[o.index(x, y, z)];
              vmin = std::min(vmin, s);
              vmax = std::max(vmax, s);
            }
        const double x0 = std::clamp((vmin - 0.5 - lut.storedMin) * lut.scale, 0.0, double(last));
        const double x1 = std::clamp((vmax + 0.5 - lut.storedMin) * lut.scale, 0.0, double(last));
        const int ea = std::max(int(std::floor(x0)) - 1, 0);
        const int eb = std::min(int(std::floor(x1)) + 2, last);
        out[(cz * size_t(cells.y) + size_t(cy)) * size_t(cells.x) + size_t(cx)] =
            opaqueBefore[size_t(eb) + 1] - opaqueBefore[size_t(ea)] > 0;
      }
  });
  return out;
}

}  // namespace voxray
