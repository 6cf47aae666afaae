#include "icet_frame.h"

#include <IceT.h>
#include <IceTMPI.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "voxray/io/error.h"
#include "voxray/io/parallel.h"

namespace voxray::mpi {

namespace {

// IceT's draw callback is a plain function without user data: the frame being drawn.
struct FrameInProgress {
  MultiDeviceRenderer* renderer = nullptr;
  const RenderParams* params = nullptr;
  std::string error;
  double renderMs = 0.0, copyMs = 0.0;
};
FrameInProgress* current = nullptr;

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// kernels' to_rgba8 (and compositeParts): round to nearest even of clamp(c, 0, 1) * 255.
uint8_t toByte(float c) { return uint8_t(std::nearbyint(std::clamp(c, 0.0f, 1.0f) * 255.0f)); }

// 2^-24: sample indices are below 2^24 (the kernels' bound on a ray's count), so index *
// 2^-24 is exact and below 1.
constexpr float kIndexDepth = 1.0f / 16777216.0f;

void drawPart(const IceTDouble*, const IceTDouble*, const IceTFloat*, const IceTInt* viewport,
              IceTImage result) {
  FrameInProgress& f = *current;
  const RenderParams& p = *f.params;
  const int w = int(icetImageGetWidth(result)), h = int(icetImageGetHeight(result));
  const bool bytes = icetImageGetColorFormat(result) == ICET_IMAGE_COLOR_RGBA_UBYTE;
  IceTFloat* colour = bytes ? nullptr : icetImageGetColorf(result);
  IceTUByte* colourBytes = bytes ? icetImageGetColorub(result) : nullptr;
  IceTFloat* depth = icetImageGetDepthFormat(result) == ICET_IMAGE_DEPTH_FLOAT
                         ? icetImageGetDepthf(result)
                         : nullptr;
  // IceT reads only VIEWPORT (x, y, width, height; rows bottom up) of this image: the
  // projection of this rank's bounds. The rest is left as it is.
  const int x0 = std::clamp(int(viewport[0]), 0, w), y0 = std::clamp(int(viewport[1]), 0, h);
  const int x1 = std::clamp(x0 + int(viewport[2]), x0, w);
  const int y1 = std::clamp(y0 + int(viewport[3]), y0, h);
  auto clearRow = [&](int y) {
    const size_t at = size_t(y) * size_t(w);
    if (bytes)
      std::fill(colourBytes + (at + size_t(x0)) * 4, colourBytes + (at + size_t(x1)) * 4, 0);
    else
      std::fill(colour + (at + size_t(x0)) * 4, colour + (at + size_t(x1)) * 4, 0.0f);
    if (depth) std::fill(depth + at + size_t(x0), depth + at + size_t(x1), 1.0f);
  };
  if (w != p.width || h != p.height) {
    for (int y = y0; y < y1; ++y) clearRow(y);
    f.error = "IceT asked for a " + std::to_string(w) + "x" + std::to_string(h) +
              " image, the frame is " + std::to_string(p.width) + "x" + std::to_string(p.height);
    return;
  }
  const auto start = Clock::now();
  std::vector<PartImage> parts;
  try {
    parts = f.renderer->renderParts(p);
  } catch (const Error& e) {
    for (int y = y0; y < y1; ++y) clearRow(y);
    f.error = e.what();  // drawn empty: the frame completes on every rank, then all stop
    return;
  }
  f.renderMs = msSince(start);
  const PartImage& part = parts.at(0);
  const auto copyStart = Clock::now();
  // Rows in parallel: a 4K part is 133 MB of float RGBA, a copy one core takes tens of ms for.
  parallelFor(size_t(y1 - y0), [&](size_t row) {
    const int y = y0 + int(row);
    // IceT's rows run bottom up (OpenGL's), the part's top down.
    const size_t from = size_t(h - 1 - y) * size_t(w), to = size_t(y) * size_t(w);
    for (int x = x0; x < x1; ++x) {
      const float* c = part.colour + (from + size_t(x)) * 4;
      if (bytes) {
        // Premultiplied colour to the nearest 8-bit level (halves up: toByte's nearbyint is a
        // library call per channel, 20-35 ms of a 4K frame on the H200's host); IceT's byte
        // "over" then rounds once per blend (icet_frame.h).
        for (int k = 0; k < 4; ++k)
          colourBytes[(to + size_t(x)) * 4 + size_t(k)] =
              uint8_t(std::clamp(c[k], 0.0f, 1.0f) * 255.0f + 0.5f);
      } else {
        std::copy(c, c + 4, colour + (to + size_t(x)) * 4);
      }
      if (!depth) continue;
      // No sample or no hit: IceT's empty depth 1.
      depth[to + size_t(x)] = c[3] <= 0.0f          ? 1.0f
                              : p.mode == Mode::Iso ? part.order[from + size_t(x)] * kIndexDepth
                                                    : 0.5f * (1.0f - c[0]);  // mip: grey in r
    }
  });
  f.copyMs = msSince(copyStart);
}

}  // namespace

IcetCompositor::IcetCompositor(MPI_Comm comm) : comm_(comm) {
  IceTCommunicator c = icetCreateMPICommunicator(comm);
  communicator_ = c;
  context_ = icetCreateContext(c);
  icetStrategy(ICET_STRATEGY_SEQUENTIAL);  // one tile: the single-image strategy composites
  icetSingleImageStrategy(ICET_SINGLE_IMAGE_STRATEGY_AUTOMATIC);
  icetEnable(ICET_COMPOSITE_ONE_BUFFER);
  icetDisable(ICET_CORRECT_COLORED_BACKGROUND);  // the background is added on rank 0
}

IcetCompositor::~IcetCompositor() {
  icetDestroyContext(static_cast<IceTContext>(context_));
  icetDestroyMPICommunicator(static_cast<IceTCommunicator>(communicator_));
}

void IcetCompositor::drawFrame(MultiDeviceRenderer& renderer, const RenderParams& p,
                               const std::vector<int>& rankOrder,
                               const std::optional<NdcBox>& bounds, IcetColour colour, Image* out,
                               IcetFrameStats* stats, std::string* error) {
  icetSetContext(static_cast<IceTContext>(context_));
  icetSetColorFormat(colour == IcetColour::Bytes ? ICET_IMAGE_COLOR_RGBA_UBYTE
                                                 : ICET_IMAGE_COLOR_RGBA_FLOAT);
  // Without bounds IceT takes the part to cover the whole image. The matrices are identities,
  // so the box in normalised device coordinates is what IceT projects.
  if (bounds)
    icetBoundingBoxd(bounds->x0, bounds->x1, bounds->y0, bounds->y1, 0.0, 0.0);
  else
    icetBoundingVertices(0, ICET_DOUBLE, 0, 0, nullptr);
  icetResetTiles();
  icetAddTile(0, 0, p.width, p.height, 0);  // one tile, shown by rank 0
  icetPhysicalRenderSize(p.width, p.height);
  if (p.mode == Mode::Dvr) {
    icetCompositeMode(ICET_COMPOSITE_MODE_BLEND);
    icetSetDepthFormat(ICET_IMAGE_DEPTH_NONE);
    icetEnable(ICET_ORDERED_COMPOSITE);
    std::vector<IceTInt> order(rankOrder.begin(), rankOrder.end());
    icetCompositeOrder(order.data());
  } else {
    icetCompositeMode(ICET_COMPOSITE_MODE_Z_BUFFER);
    icetSetDepthFormat(ICET_IMAGE_DEPTH_FLOAT);
    icetDisable(ICET_ORDERED_COMPOSITE);
  }
  icetDrawCallback(drawPart);
  FrameInProgress frame;
  frame.renderer = &renderer;
  frame.params = &p;
  current = &frame;
  // Identity matrices: the bounds are given in normalised device coordinates already.
  const IceTDouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const IceTFloat clear[4] = {0, 0, 0, 0};
  const auto start = Clock::now();
  IceTImage result = icetDrawFrame(identity, identity, clear);
  const double frameMs = msSince(start);
  current = nullptr;
  if (error) *error = frame.error;
  if (stats) {
    IceTDouble seconds = 0.0;
    stats->frameMs = frameMs;
    stats->renderMs = frame.renderMs;
    icetGetDoublev(ICET_COMPOSITE_TIME, &seconds);
    stats->compositeMs = seconds * 1e3;
    stats->copyMs = frame.copyMs;
    icetGetDoublev(ICET_COMPRESS_TIME, &seconds);
    stats->compressMs = seconds * 1e3;
    icetGetDoublev(ICET_BLEND_TIME, &seconds);
    stats->blendMs = seconds * 1e3;
    icetGetDoublev(ICET_COLLECT_TIME, &seconds);
    stats->collectMs = seconds * 1e3;
    icetGetDoublev(ICET_TOTAL_DRAW_TIME, &seconds);
    stats->icetTotalMs = seconds * 1e3;
  }
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank != 0 || !out) return;
  const int w = int(icetImageGetWidth(result)), h = int(icetImageGetHeight(result));
  const bool bytes = icetImageGetColorFormat(result) == ICET_IMAGE_COLOR_RGBA_UBYTE;
  const IceTFloat* colourFloats = bytes ? nullptr : icetImageGetColorcf(result);
  const IceTUByte* colourBytes = bytes ? icetImageGetColorcub(result) : nullptr;
  out->width = w;
  out->height = h;
  out->rgba.assign(size_t(w) * size_t(h) * 4, 255);
  const glm::vec3 bg(p.background);
  parallelFor(size_t(h), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < w; ++x) {
      const size_t at = (size_t(h - 1 - y) * size_t(w) + size_t(x)) * 4;
      glm::vec4 c;
      if (bytes)
        c = glm::vec4(colourBytes[at], colourBytes[at + 1], colourBytes[at + 2],
                      colourBytes[at + 3]) /
            255.0f;
      else
        c = glm::vec4(colourFloats[at], colourFloats[at + 1], colourFloats[at + 2],
                      colourFloats[at + 3]);
      glm::vec3 rgb;
      if (p.mode == Mode::Dvr)
        rgb = glm::vec3(c) + (1.0f - c.a) * bg;  // as compositeParts
      else if (p.mode == Mode::Iso)
        rgb = c.a > 0.0f ? glm::vec3(c) : bg;
      else
        rgb = c.a > 0.0f ? glm::vec3(c.r) : bg;
      uint8_t* o = &out->rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
      o[0] = toByte(rgb.x);
      o[1] = toByte(rgb.y);
      o[2] = toByte(rgb.z);
    }
  });
}

}  // namespace voxray::mpi
