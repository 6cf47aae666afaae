#include "voxray/io/segment_edit.h"

#include <cmath>
#include <string>

#include "mask_box.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

void checkLabel(const Segmentation& s, uint8_t label, bool zeroAllowed) {
  if (label == 0 && zeroAllowed) return;
  if (label == 0 || !s.find(label))
    throw inputError("There is no segment with label " + std::to_string(label) +
                     ": add the segment before painting it.");
}

void checkRadius(double radiusMm) {
  if (!std::isfinite(radiusMm) || radiusMm <= 0.0 || radiusMm > 500.0)
    throw inputError("A brush radius of " + std::to_string(radiusMm) +
                     " mm: give a radius from above 0 to 500 mm.");
}

// Applies `next(old)` to the voxels of the box where `chosen(x, y, z)`, recording the box's
// old labels; the patch shrinks to nothing when no voxel changed.
template <class Chosen, class Next>
LabelPatch edit(Segmentation& s, Box b, Chosen&& chosen, Next&& next) {
  LabelPatch p;
  b = Box{glm::max(b.lo, glm::ivec3(0)), glm::min(b.hi, s.grid.dims)};
  if (b.empty()) return p;
  p.lo = b.lo;
  p.hi = b.hi;
  const glm::ivec3 d = b.dims();
  p.labels.resize(size_t(d.x) * size_t(d.y) * size_t(d.z));
  bool changed = false;
  size_t i = 0;
  for (int z = b.lo.z; z < b.hi.z; ++z)
    for (int y = b.lo.y; y < b.hi.y; ++y)
      for (int x = b.lo.x; x < b.hi.x; ++x, ++i) {
        uint8_t& l = s.labels[s.grid.index(x, y, z)];
        p.labels[i] = l;
        if (!chosen(x, y, z)) continue;
        const uint8_t n = next(l, s.grid.index(x, y, z));
        changed = changed || n != l;
        l = n;
      }
  if (!changed) p = LabelPatch{};
  return p;
}

auto painter(uint8_t label, EditPolicy policy) {
  return [=](uint8_t old, size_t = 0) {
    return old == 0 || old == label || policy.overwriteOthers ? label : old;
  };
}

auto eraser(uint8_t label) {
  return [=](uint8_t old, size_t = 0) { return label == 0 || old == label ? uint8_t(0) : old; };
}

// The voxels whose centres lie within r mm of the centre (a fractional voxel index), in a
// plane of `axis` (-1: the whole ball).
struct Ball {
  glm::dvec3 centre, spacing;
  double r2;
  int axis;
  int slice;
  bool operator()(int x, int y, int z) const {
    const glm::dvec3 d = (glm::dvec3(x, y, z) - centre) * spacing;
    if (axis >= 0 && glm::ivec3(x, y, z)[axis] != slice) return false;
    return glm::dot(d, d) <= r2;
  }
  Box box() const {
    const glm::dvec3 reach = std::sqrt(r2) / spacing;
    Box b{glm::ivec3(glm::ceil(centre - reach)), glm::ivec3(glm::floor(centre + reach)) + 1};
    if (axis >= 0) {
      b.lo[axis] = slice;
      b.hi[axis] = slice + 1;
    }
    return b;
  }
};

Ball ball(const Segmentation& s, glm::dvec3 centre, double radiusMm, int axis) {
  checkRadius(radiusMm);
  if (!glm::all(glm::lessThan(glm::abs(centre), glm::dvec3(1e7))))
    throw inputError("The brush's centre is not a position in the volume.");
  if (axis < -1 || axis > 2) throw inputError("A slice's axis is 0 (i), 1 (j) or 2 (k).");
  // A disc lies in the slice nearest the centre and measures distances within it.
  const int slice = axis >= 0 ? int(std::lround(centre[axis])) : 0;
  if (axis >= 0) centre[axis] = slice;
  // A tolerance of 1e-9 mm² keeps a voxel exactly on the radius inside.
  return Ball{centre, s.grid.spacingMm, radiusMm * radiusMm + 1e-9, axis, slice};
}

}  // namespace

void swapPatch(Segmentation& s, LabelPatch& p) {
  if (p.empty()) return;
  const glm::ivec3 d = p.hi - p.lo;
  if (glm::any(glm::lessThan(p.lo, glm::ivec3(0))) ||
      glm::any(glm::greaterThan(p.hi, s.grid.dims)) ||
      p.labels.size() != size_t(d.x) * size_t(d.y) * size_t(d.z))
    throw Error(Error::Kind::Internal, "An undo patch does not fit the label map");
  size_t i = 0;
  for (int z = p.lo.z; z < p.hi.z; ++z)
    for (int y = p.lo.y; y < p.hi.y; ++y)
      for (int x = p.lo.x; x < p.hi.x; ++x, ++i)
        std::swap(s.labels[s.grid.index(x, y, z)], p.labels[i]);
}

LabelPatch paintSphere(Segmentation& s, glm::dvec3 centre, double radiusMm, uint8_t label,
                       EditPolicy policy) {
  checkLabel(s, label, false);
  const Ball b = ball(s, centre, radiusMm, -1);
  return edit(s, b.box(), b, painter(label, policy));
}

LabelPatch eraseSphere(Segmentation& s, glm::dvec3 centre, double radiusMm, uint8_t label) {
  checkLabel(s, label, true);
  const Ball b = ball(s, centre, radiusMm, -1);
  return edit(s, b.box(), b, eraser(label));
}

LabelPatch paintDisc(Segmentation& s, int axis, glm::dvec3 centre, double radiusMm, uint8_t label,
                     EditPolicy policy) {
  checkLabel(s, label, false);
  const Ball b = ball(s, centre, radiusMm, axis);
  return edit(s, b.box(), b, painter(label, policy));
}

LabelPatch eraseDisc(Segmentation& s, int axis, glm::dvec3 centre, double radiusMm, uint8_t label) {
  checkLabel(s, label, true);
  const Ball b = ball(s, centre, radiusMm, axis);
  return edit(s, b.box(), b, eraser(label));
}

LabelPatch setMask(Segmentation& s, uint8_t label, const Mask& m, EditPolicy policy) {
  checkLabel(s, label, false);
  if (m.size() != s.labels.size())
    throw inputError("The mask has " + std::to_string(m.size()) + " voxels, the label map " +
                     std::to_string(s.labels.size()) + ": both must lie on the same grid.");
  // The box of what may change: the new mask's voxels and the label's old ones.
  Mask touched(m.size());
  for (size_t i = 0; i < m.size(); ++i) touched[i] = m[i] || s.labels[i] == label;
  const Box b = maskBox(s.grid, touched);
  const auto paint = painter(label, policy);
  return edit(
      s, b, [](int, int, int) { return true; },
      [&](uint8_t old, size_t i) { return m[i]           ? paint(old)
                                          : old == label ? uint8_t(0)
                                                         : old; });
}

}  // namespace voxray
