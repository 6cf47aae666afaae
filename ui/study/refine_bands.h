#pragma once
// The sharp frame after a drag, refined in bands of rows (issue 16): on 2 CPU cores a
// 1024x768 balanced CT frame takes several drag frames' time, and a camera move that came
// while it rendered had to wait for all of it. In bands, each shown over the last frame as
// it finishes, a move waits for one band at most, and the view changes every band.
// Qt-free: the render worker follows the plan; tests check it without a display.
#include <vector>

#include "no_qt.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"

namespace voxray {

struct RowBand {
  int y0 = 0, y1 = 0;  // rows [y0, y1) of the frame
  bool operator==(const RowBand& o) const { return y0 == o.y0 && y1 == o.y1; }
};

// A sixteenth of a 1024x768 frame, a quarter of the rays of its drag frame (512x384).
// Measured on the 512x512x400 CT (docs/bench/README.md, "Session 6", bench --stall): the
// costliest band (the middle, through the body) took 46 ms of CPU in 16 bands, 85 in 8 and
// 156 in 4, and the bands together as much as the whole frame (308 ms) in each case.
inline constexpr long kRefineBandPixels = 128L * 384L;
// Bands start at multiples of 16 rows: whole 4x4 work-groups of the CPU's 4x4 (16-lane)
// and 4x2 (8-lane) ray packets, so that no band renders rows of its neighbour.
inline constexpr int kRefineBandAlign = 16;

// The bands of a WIDTH x HEIGHT sharp frame: one band (the frame whole) up to
// kRefineBandPixels, else ceil(pixels / kRefineBandPixels) bands of nearly equal height,
// in the order they are rendered: the middle band first, then outwards alternately below
// and above (the user looks at the middle). MAXBANDS caps the count (1: never banded).
// BANDPIXELS in place of kRefineBandPixels (benchmarks).
std::vector<RowBand> refineBands(int width, int height, int maxBands = 32,
                                 long bandPixels = kRefineBandPixels);

// The bands the 3D view asks for frame P: none (a whole frame) for a drag frame and for
// lighting cinematic (its path tracer refines in passes of its own), else refineBands.
std::vector<RowBand> viewFrameBands(const RenderParams& p, bool interactive);

// SRC scaled to WIDTH x HEIGHT by nearest pixel, as the 3D view draws a smaller drag
// frame (QPainter without smoothing): the bands are painted over what the user already
// sees. SRC of that size is returned as is; an empty SRC gives a black frame.
Image upscaleNearest(const Image& src, int width, int height);

}  // namespace voxray
