// The one plot canvas of the lab (engine/lab/include/voxray/lab/plot_canvas.h), which draws
// both `voxray-cli accuracy --plot` and `bench --plot`, and the accuracy plot drawn on it:
// pixels where the primitives, the glyphs and the plotted points must land.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "voxray/lab/accuracy_plot.h"
#include "voxray/lab/plot_canvas.h"

namespace voxray {

namespace {

std::vector<int> rgb(const Image& img, int x, int y) {
  const uint8_t* p = img.pixel(x, y);
  return {p[0], p[1], p[2]};
}

std::vector<int> rgb(PlotRgb c) { return {c.r, c.g, c.b}; }

const std::vector<int> kWhite{255, 255, 255}, kBlack{0, 0, 0};

// The rows of '#' a text leaves in the canvas, for a glyph-by-glyph comparison.
std::vector<std::string> inked(const Image& img, int x0, int y0, int w, int h) {
  std::vector<std::string> rows;
  for (int y = y0; y < y0 + h; ++y) {
    std::string r;
    for (int x = x0; x < x0 + w; ++x) r += rgb(img, x, y) == kBlack ? '#' : '.';
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST(PlotCanvas, BoxesAreInclusiveAndDrawingOutsideTheCanvasIsIgnored) {
  PlotCanvas c(8, 6, {10, 20, 30});
  c.box(-5, -5, 1, 2, {0, 0, 0});  // clipped at the top-left corner
  c.pixel(8, 0, {0, 0, 0});        // one past the right edge: nothing
  EXPECT_EQ(rgb(c.image(), 0, 0), kBlack);
  EXPECT_EQ(rgb(c.image(), 1, 2), kBlack);
  EXPECT_EQ(rgb(c.image(), 2, 2), (std::vector<int>{10, 20, 30}));
  EXPECT_EQ(rgb(c.image(), 1, 3), (std::vector<int>{10, 20, 30}));
  EXPECT_EQ(rgb(c.image(), 7, 0), (std::vector<int>{10, 20, 30}));
  EXPECT_EQ(c.image().rgba[3], 255);
}

TEST(PlotCanvas, DashedLinesDrawEightPixelsAndSkipSix) {
  PlotCanvas c(40, 3);
  c.line(0, 1, 39, 1, {0, 0, 0}, 1, true);
  std::string row;
  for (int x = 0; x < 30; ++x) row += rgb(c.image(), x, 1) == kBlack ? '#' : '.';
  EXPECT_EQ(row, "########......########......##");
  EXPECT_EQ(rgb(c.image(), 5, 0), kWhite);  // width 1: the rows beside stay clear
}

TEST(PlotCanvas, WideLinesAndDiscsCoverTheirWidthAndRadius) {
  PlotCanvas c(20, 20);
  c.line(2, 10, 17, 10, {0, 0, 0}, 3);
  EXPECT_EQ(rgb(c.image(), 9, 9), kBlack);
  EXPECT_EQ(rgb(c.image(), 9, 11), kBlack);
  EXPECT_EQ(rgb(c.image(), 9, 12), kWhite);
  PlotCanvas d(20, 20);
  d.disc(10, 10, 3, {0, 0, 0});
  EXPECT_EQ(rgb(d.image(), 13, 10), kBlack);
  EXPECT_EQ(rgb(d.image(), 10, 7), kBlack);
  EXPECT_EQ(rgb(d.image(), 13, 13), kWhite);  // outside the circle, inside its square
}

TEST(PlotCanvas, TextUsesTheFiveBySevenFontAndPrintsLowerCaseAsUpper) {
  PlotCanvas c(24, 7);
  c.text(0, 0, "1e", {0, 0, 0}, 1);
  EXPECT_EQ(inked(c.image(), 0, 0, 12, 7), (std::vector<std::string>{
                                               "..#...#####.",
                                               ".##...#.....",
                                               "..#...#.....",
                                               "..#...####..",
                                               "..#...#.....",
                                               "..#...#.....",
                                               ".###..#####.",
                                           }));
  EXPECT_EQ(PlotCanvas::textWidth("1e", 1), 12);
  EXPECT_EQ(PlotCanvas::textWidth("1e"), 24);
  EXPECT_EQ(PlotCanvas::textHeight(3), 21);
  PlotCanvas big(24, 14);
  big.text(0, 0, "1", {0, 0, 0});  // scale 2: each font pixel is 2x2
  EXPECT_EQ(rgb(big.image(), 4, 0), kBlack);
  EXPECT_EQ(rgb(big.image(), 5, 1), kBlack);
  EXPECT_EQ(rgb(big.image(), 3, 0), kWhite);
}

TEST(PlotCanvas, SeriesColoursFollowTableauTenAndWrap) {
  EXPECT_EQ(rgb(seriesColour(0)), (std::vector<int>{31, 119, 180}));
  EXPECT_EQ(rgb(seriesColour(1)), (std::vector<int>{214, 39, 40}));
  EXPECT_EQ(rgb(seriesColour(10)), rgb(seriesColour(0)));
  EXPECT_NE(rgb(seriesColour(9)), rgb(seriesColour(8)));
}

TEST(AccuracyPlot, PointsLandOnTheirLogLogPositionsAndTheFrontierIsJoined) {
  // Image RMSE panel: x spans decades 0 ... 2 over pixels 590 ... 1030, y decades -3 ... -1
  // over pixels 440 ... 40 (left, top, width 440, height 400 of the right panel).
  SweepRow fast, slow, other;
  fast.scene = slow.scene = "ml41";
  other.scene = "sphere64";
  fast.msPerFrame = 1.0, fast.image.rmse = 0.1;
  slow.msPerFrame = 100.0, slow.image.rmse = 0.001;
  other.msPerFrame = 10.0, other.image.rmse = 0.1;  // dominated by `fast`: not joined
  Image img = accuracyPlot({fast, slow, other});
  ASSERT_EQ(img.width, 1040);
  ASSERT_EQ(img.height, 500);
  const std::vector<int> first = rgb(seriesColour(0)), second = rgb(seriesColour(1));
  EXPECT_EQ(rgb(img, 590, 40), first);
  EXPECT_EQ(rgb(img, 1030, 440), first);
  EXPECT_EQ(rgb(img, 810, 40), second);
  EXPECT_EQ(rgb(img, 810, 240), (std::vector<int>{60, 60, 60}));    // the frontier's midpoint
  EXPECT_EQ(rgb(img, 700, 40), (std::vector<int>{225, 225, 225}));  // the 0.1 grid line
  // Legend: one swatch per scene, in order of appearance.
  EXPECT_EQ(rgb(img, 820, 20), first);
  EXPECT_EQ(rgb(img, 844, 20), second);
  // The right panel's axes; the iso panel (no surface, no hit points) keeps only its titles:
  // "MS PER FRAME" centred under it, its 'M' starting at 70 + (440 - 12 * 12) / 2.
  EXPECT_EQ(rgb(img, 590, 300), kBlack);
  EXPECT_EQ(rgb(img, 70, 440), kWhite);
  EXPECT_EQ(rgb(img, 218, 470), kBlack);
  EXPECT_EQ(rgb(img, 217, 470), kWhite);
}

}  // namespace voxray
