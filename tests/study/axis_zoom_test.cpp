// Issue 35: the zoomable axes of the transfer-function editors (axis_zoom.h). Pixel and value
// map back exactly, a zoom keeps the value under the cursor where it was, a drag pans by whole
// pixels, and "fit to the visible range" drops the bins that hold almost no voxels.
#include <cmath>

#include <gtest/gtest.h>

#include "axis_zoom.h"
#include "voxray/io/histogram.h"

using namespace voxray;

namespace {

// Round trips go through one multiplication and one division each way: far below 1e-9 for
// values of a few thousand HU and pixels of a few thousand.
constexpr double kExact = 1e-9;

}  // namespace

TEST(AxisZoom, PixelAndValueRoundTripExactly) {
  for (AxisRange r : {AxisRange{-1024.0, 3071.0}, AxisRange{-0.37, 12.9}, AxisRange{0.0, 200.0}})
    for (auto [p0, length] : {std::pair{8.0, 623.0}, std::pair{291.5, -273.0}}) {
      for (double v = r.lo - 100.0; v <= r.hi + 100.0; v += r.span() / 97.0)
        EXPECT_NEAR(axisValue(r, axisPixel(r, v, p0, length), p0, length), v, kExact);
      for (double px = -50.0; px < 700.0; px += 0.25)
        EXPECT_NEAR(axisPixel(r, axisValue(r, px, p0, length), p0, length), px, kExact);
    }
  // The ends sit at the ends of the run of pixels (negative: upwards).
  const AxisRange g{0.0, 200.0};
  EXPECT_DOUBLE_EQ(axisPixel(g, 0.0, 300.0, -200.0), 300.0);
  EXPECT_DOUBLE_EQ(axisPixel(g, 200.0, 300.0, -200.0), 100.0);
  EXPECT_DOUBLE_EQ(axisPixel(g, 50.0, 300.0, -200.0), 250.0);
}

TEST(AxisZoom, ZoomKeepsTheValueUnderTheCursor) {
  const AxisRange r{-1024.0, 3071.0};
  const double p0 = 8.0, length = 600.0;
  for (double cursor : {8.0, 131.0, 400.5, 608.0}) {
    const double hu = axisValue(r, cursor, p0, length);
    for (double notches : {1.0, 3.0, -2.0}) {
      const double f = wheelZoomFactor(notches);
      const AxisRange z = zoomAbout(r, hu, f, 1.0, 1e6);
      EXPECT_NEAR(axisPixel(z, hu, p0, length), cursor, kExact) << cursor << " " << notches;
      EXPECT_NEAR(z.span(), r.span() * f, kExact * r.span());
    }
  }
  // 20 % per notch: three notches in show 0.8^3 = 0.512 of the span.
  EXPECT_DOUBLE_EQ(wheelZoomFactor(1.0), 0.8);
  EXPECT_NEAR(wheelZoomFactor(3.0), 0.512, 1e-15);
  EXPECT_NEAR(wheelZoomFactor(-1.0), 1.25, 1e-15);
  // Cut at the least span, the value still keeps its pixel.
  const AxisRange tight = zoomAbout({100.0, 110.0}, 103.0, 0.01, 1.0, 1e6);
  EXPECT_NEAR(tight.span(), 1.0, kExact);
  EXPECT_NEAR(axisPixel(tight, 103.0, 0.0, 500.0), axisPixel({100.0, 110.0}, 103.0, 0.0, 500.0),
              kExact);
  // A zero, negative or non-finite factor changes nothing.
  EXPECT_EQ(zoomAbout(r, 0.0, 0.0, 1.0, 1e6), r);
  EXPECT_EQ(zoomAbout(r, 0.0, std::nan(""), 1.0, 1e6), r);
}

TEST(AxisZoom, PanMovesWhatWasUnderAPixelByTheDrag) {
  const AxisRange r{-200.0, 300.0};
  for (double length : {400.0, -250.0}) {
    const double p0 = length > 0 ? 10.0 : 260.0;
    const AxisRange moved = panByPixels(r, 37.0, length);
    for (double px : {p0, p0 + 0.3 * length, p0 + length}) {
      const double v = axisValue(r, px, p0, length);
      EXPECT_NEAR(axisPixel(moved, v, p0, length), px + 37.0, kExact);
    }
    EXPECT_NEAR(moved.span(), r.span(), kExact);
  }
  // 37 pixels of 400 over 500 HU: 46.25 HU towards lower values.
  EXPECT_NEAR(panByPixels(r, 37.0, 400.0).lo, -246.25, kExact);
}

TEST(AxisZoom, OccupiedRangeDropsBinsBelowTheFraction) {
  // 8 bins of 100 over 0 ... 800; 4017 counts.
  const std::vector<uint64_t> counts{0, 0, 5, 1000, 3000, 10, 0, 2};
  EXPECT_EQ(occupiedRange(counts, 0.0, 800.0, 1e-3), (AxisRange{200.0, 600.0}));  // >= 4.017
  EXPECT_EQ(occupiedRange(counts, 0.0, 800.0, 1e-2), (AxisRange{300.0, 500.0}));  // >= 40.17
  // Nothing counted: the whole axis.
  EXPECT_EQ(occupiedRange({0, 0, 0}, -5.0, 5.0, 1e-3), (AxisRange{-5.0, 5.0}));
  EXPECT_EQ(occupiedRange({}, -5.0, 5.0, 1e-3), (AxisRange{-5.0, 5.0}));
}

TEST(AxisZoom, VisibleHuRangeLeavesOutAFewOutliers) {
  // A CT-like histogram over stored -1024 ... 3071 (slope 1, intercept 0): air, soft tissue,
  // bone and five voxels of metal at 3000 HU (0.0003 % of them).
  StoredHistogram h;
  h.min = -1024;
  h.max = 3071;
  h.counts.assign(4096, 0);
  auto put = [&](int hu, uint64_t n) {
    h.counts[size_t(hu + 1024)] += n;
    h.total += n;
  };
  put(-1000, 1000000);
  put(40, 500000);
  put(1200, 20000);
  put(3000, 5);
  // 256 bins of 16 HU from -1024: -1000 is in the bin from -1008, 1200 in the one to 1216.
  EXPECT_EQ(visibleHuRange(h, 1.0, 0.0), (AxisRange{-1008.0, 1216.0}));
  // Stored values with a slope and intercept (a CT stored 0 ... 4095 with intercept -1024 and
  // slope 0.5): the same voxels at half the HU.
  StoredHistogram s = h;
  s.min = 0;
  s.max = 4095;
  EXPECT_EQ(visibleHuRange(s, 0.5, -1024.0).lo, -1024.0 + 0.5 * 16.0);
  EXPECT_EQ(visibleHuRange(s, 0.5, -1024.0).hi, -1024.0 + 0.5 * 16.0 * 140.0);
  // An empty histogram: nothing to fit.
  EXPECT_EQ(visibleHuRange(StoredHistogram{}, 1.0, 0.0), (AxisRange{0.0, 1.0}));
}
