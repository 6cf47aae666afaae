#include "stack_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "voxray/io/error.h"
#include "voxray/io/statistics.h"

namespace voxray::dicom {
namespace {

constexpr double kTiltToleranceDeg = 0.05;
// Uneven when gaps differ by more than this share of the median gap (plus 0.01 mm for
// positions printed with few digits).
constexpr double kGapTolerance = 0.02;
// Never resample onto more than this many times the stored slice count.
constexpr int kMaxSliceGrowth = 4;

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f mm", v);
  return buf;
}

// The slice spacing when the stack has no usable positions.
double nominalSpacing(const FrameHeader& f) {
  if (f.spacingBetweenSlices > 0) return f.spacingBetweenSlices;
  if (f.sliceThickness > 0) return f.sliceThickness;
  return 1.0;
}

}  // namespace

StackGeometry analyseStack(const std::vector<FrameHeader>& frames) {
  StackGeometry g;
  const FrameHeader& f0 = frames.front();
  const glm::dvec3 row = f0.rowDir, col = f0.colDir, n = f0.normal();
  Grid& s = g.source;
  s.dims = {f0.columns, f0.rows, int(frames.size())};
  s.axes = glm::dmat3(row, col, n);
  s.origin = f0.position;
  s.spacing = {f0.pixelSpacing.x, f0.pixelSpacing.y, nominalSpacing(f0)};
  if (!f0.hasPixelSpacing)
    g.warnings.push_back("the images carry no PixelSpacing; 1 mm pixels assumed");
  for (auto& f : frames) g.offsets.push_back(glm::dot(f.position - f0.position, n));

  if (frames.size() < 2 || !f0.hasPosition) {
    if (!f0.hasPosition && frames.size() > 1)
      g.warnings.push_back(
          "the images carry no ImagePositionPatient: slices stacked in "
          "acquisition order, " +
          mm(s.spacing.z) + " apart (from the header)");
    g.target = s;
    return g;
  }
  // Tilt: the stack advances along (last - first), which is not the normal when the
  // gantry was tilted; the slices are then sheared against each other. Gaps are measured
  // along that advance, as the scanner table moved.
  const glm::dvec3 advance = glm::normalize(frames.back().position - f0.position);
  g.tiltDegrees = glm::degrees(std::acos(std::clamp(std::abs(glm::dot(advance, n)), 0.0, 1.0)));
  const bool tilted = g.tiltDegrees > kTiltToleranceDeg;
  std::vector<double> gaps;
  for (size_t k = 1; k < frames.size(); ++k)
    gaps.push_back(glm::dot(frames[k].position - frames[k - 1].position, advance));
  g.minGap = *std::min_element(gaps.begin(), gaps.end());
  g.maxGap = *std::max_element(gaps.begin(), gaps.end());
  g.medianGap = quantile(gaps, 0.5);  // one of the gaps, not a mean of two
  if (g.minGap <= 1e-3)
    throw inputError("two slices of series " + std::to_string(f0.seriesNumber) +
                     " lie at the same position; they cannot form one volume");
  s.spacing.z = g.medianGap;

  const double tol = kGapTolerance * g.medianGap + 0.01;
  const bool uneven = g.maxGap - g.minGap > tol;
  bool onlyMissing = uneven;
  for (double gap : gaps) {
    double ratio = gap / g.medianGap;
    double whole = std::round(ratio);
    if (whole < 1 || std::abs(gap - whole * g.medianGap) > tol * whole) onlyMissing = false;
    if (whole >= 2) g.missingSlices += int(whole) - 1;
  }
  if (!onlyMissing) g.missingSlices = 0;
  if (uneven && onlyMissing) {
    g.warnings.push_back(std::to_string(g.missingSlices) + " slice(s) missing (gaps of " +
                         mm(g.maxGap) + " in a " + mm(g.medianGap) +
                         " stack): filled by interpolation");
  } else if (uneven) {
    g.warnings.push_back("uneven slice gaps (min " + mm(g.minGap) + ", max " + mm(g.maxGap) +
                         "): resampled to a uniform grid");
  }
  if (tilted) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "gantry tilt of %.1f degrees (from slice positions): sheared slices "
                  "resampled to an orthogonal grid",
                  g.tiltDegrees);
    g.warnings.push_back(buf);
  }
  g.needsResampling = uneven || tilted;
  if (!g.needsResampling) {
    g.target = s;
    return g;
  }

  // Target axes: i along the rows; k along the stacking direction made orthogonal to i.
  Grid& t = g.target;
  glm::dvec3 k = tilted ? glm::normalize(advance - glm::dot(advance, row) * row) : n;
  glm::dvec3 j = glm::normalize(glm::cross(k, row));
  t.axes = glm::dmat3(row, j, k);
  // The box of every slice corner in the target frame. Along k too: a tilted slice
  // reaches beyond the table positions of the first and last slice, and clipping the box
  // to those positions would drop the tissue there.
  glm::dvec3 lo(1e300), hi(-1e300);
  for (auto& f : frames)
    for (int cy : {0, f0.rows - 1})
      for (int cx : {0, f0.columns - 1}) {
        glm::dvec3 p = f.position + double(cx) * s.spacing.x * row +
                       double(cy) * s.spacing.y * col - f0.position;
        glm::dvec3 q{glm::dot(p, row), glm::dot(p, j), glm::dot(p, k)};
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
      }
  const glm::dvec3 extent = hi - lo;
  double dz = (uneven && !onlyMissing) ? g.minGap : g.medianGap;
  // The cap on growth is taken over the table positions' range, as before a tilted grid
  // reached past them: holding every pixel keeps the finer step, not a coarser one.
  const double span = glm::dot(frames.back().position - f0.position, k);
  dz = std::max(dz, span / (kMaxSliceGrowth * double(frames.size())));
  // Whole steps from the first corner to the last: the grid ends on the box's far side.
  const auto steps = [](double length, double step) {
    return std::max(1.0, std::ceil(length / step - 1e-6));
  };
  dz = extent.z / steps(extent.z, dz);
  t.spacing = {s.spacing.x, s.spacing.y, dz};
  // In-plane, the grid keeps the pixel spacing and may end up to one pixel past the box.
  t.dims = {int(steps(extent.x, t.spacing.x)) + 1, int(steps(extent.y, t.spacing.y)) + 1,
            int(steps(extent.z, t.spacing.z)) + 1};
  t.origin = f0.position + lo.x * row + lo.y * j + lo.z * k;
  return g;
}

}  // namespace voxray::dicom
