#pragma once
// A zoomable axis of the transfer-function editors (issue 35): the HU axis of the 1D curve and
// both axes of the 2D histogram. A range of values is shown over a run of pixels; the wheel
// zooms about the value under the cursor (it stays under it), a drag pans by whole pixels,
// "fit" shows the values that hold voxels, "reset" the whole axis. Pure arithmetic, so the
// widgets keep no mapping of their own.
#include <cstdint>
#include <vector>

#include "no_qt.h"

namespace voxray {

struct StoredHistogram;

struct AxisRange {
  double lo = 0.0, hi = 1.0;
  double span() const { return hi - lo; }
  bool operator==(const AxisRange&) const = default;
};

// Pixels: the axis starts at pixel P0 and runs LENGTH pixels (negative: values grow towards
// smaller pixels, as a y axis drawn upwards). LO sits at P0, HI at P0 + LENGTH.
double axisPixel(const AxisRange& r, double value, double p0, double length);
double axisValue(const AxisRange& r, double pixel, double p0, double length);

// The range zoomed by FACTOR (< 1: in, > 1: out) about VALUE, which keeps its pixel. The span
// stays within MINSPAN ... MAXSPAN (the factor is cut to fit, VALUE still keeps its pixel).
AxisRange zoomAbout(const AxisRange& r, double value, double factor, double minSpan,
                    double maxSpan);
// The factor of NOTCHES wheel notches (120 eighths of a degree each): 20 % in per notch
// forward, the same back.
double wheelZoomFactor(double notches);
// The range moved so that what was under pixel A is under pixel A + PIXELS (a drag of PIXELS;
// LENGTH as for axisPixel).
AxisRange panByPixels(const AxisRange& r, double pixels, double length);

// The range of equal bins over [LO, HI] (COUNTS, in order) from the first to the last bin
// that holds at least FRACTION of all the counts: where the voxels are, without the few
// outliers (a metal streak, padding) that would squeeze the rest. Empty counts: {lo, hi}.
AxisRange occupiedRange(const std::vector<uint64_t>& counts, double lo, double hi, double fraction);
// The HU range of a stored-value histogram that holds voxels (occupiedRange over BINS equal
// bins of the histogram's HU range). What "fit to the visible range" shows.
inline constexpr double kVisibleFraction = 1e-3;
AxisRange visibleHuRange(const StoredHistogram& h, double slope, double intercept,
                         double fraction = kVisibleFraction, int bins = 256);

}  // namespace voxray
