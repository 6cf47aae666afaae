#include "icet_frame.h"

#include <IceT.h>
#include <IceTMPI.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "voxray/io/error.h"

namespace voxray::mpi {

namespace {

// IceT's draw callback is a plain function without user data: the frame being drawn.
struct FrameInProgress {
  MultiDeviceRenderer* renderer = nullptr;
  const RenderParams* params = nullptr;
  std::string error;
  double renderMs = 0.0;
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

void drawPart(const IceTDouble*, const IceTDouble*, const IceTFloat*, const IceTInt*,
              IceTImage result) {
  FrameInProgress& f = *current;
  const RenderParams& p = *f.params;
  const int w = int(icetImageGetWidth(result)), h = int(icetImageGetHeight(result));
  IceTFloat* colour = icetImageGetColorf(result);
  IceTFloat* depth = icetImageGetDepthFormat(result) == ICET_IMAGE_DEPTH_FLOAT
                         ? icetImageGetDepthf(result)
                         : nullptr;
  std::fill(colour, colour + size_t(w) * size_t(h) * 4, 0.0f);
  if (depth) std::fill(depth, depth + size_t(w) * size_t(h), 1.0f);
  if (w != p.width || h != p.height) {
    f.error = "IceT asked for a " + std::to_string(w) + "x" + std::to_string(h) +
              " image, the frame is " + std::to_string(p.width) + "x" + std::to_string(p.height);
    return;
  }
  const auto start = Clock::now();
  std::vector<PartImage> parts;
  try {
    parts = f.renderer->renderParts(p);
  } catch (const Error& e) {
    f.error = e.what();  // drawn empty: the frame completes on every rank, then all stop
    return;
  }
  f.renderMs = msSince(start);
  const PartImage& part = parts.at(0);
  for (int y = 0; y < h; ++y) {
    // IceT's rows run bottom up (OpenGL's), the part's top down.
    const size_t from = size_t(y) * size_t(w), to = size_t(h - 1 - y) * size_t(w);
    for (int x = 0; x < w; ++x) {
      const float* c = part.colour + (from + size_t(x)) * 4;
      std::copy(c, c + 4, colour + (to + size_t(x)) * 4);
      if (!depth || c[3] <= 0.0f) continue;  // no sample or no hit: IceT's empty depth 1
      depth[to + size_t(x)] = p.mode == Mode::Iso ? part.order[from + size_t(x)] * kIndexDepth
                                                  : 0.5f * (1.0f - c[0]);  // mip: grey in r
    }
  }
}

}  // namespace

IcetCompositor::IcetCompositor(MPI_Comm comm) : comm_(comm) {
  IceTCommunicator c = icetCreateMPICommunicator(comm);
  communicator_ = c;
  context_ = icetCreateContext(c);
  icetStrategy(ICET_STRATEGY_SEQUENTIAL);  // one tile: the single-image strategy composites
  icetSingleImageStrategy(ICET_SINGLE_IMAGE_STRATEGY_AUTOMATIC);
  icetSetColorFormat(ICET_IMAGE_COLOR_RGBA_FLOAT);
  icetEnable(ICET_COMPOSITE_ONE_BUFFER);
  icetDisable(ICET_CORRECT_COLORED_BACKGROUND);  // the background is added on rank 0
}

IcetCompositor::~IcetCompositor() {
  icetDestroyContext(static_cast<IceTContext>(context_));
  icetDestroyMPICommunicator(static_cast<IceTCommunicator>(communicator_));
}

void IcetCompositor::drawFrame(MultiDeviceRenderer& renderer, const RenderParams& p,
                               const std::vector<int>& rankOrder, Image* out, IcetFrameStats* stats,
                               std::string* error) {
  icetSetContext(static_cast<IceTContext>(context_));
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
  // No bounds are given: IceT takes each rank's part to cover the whole image (a slab's
  // projection may well do), so the matrices only pass through to the callback.
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
    icetGetDoublev(ICET_TOTAL_DRAW_TIME, &seconds);
    stats->icetTotalMs = seconds * 1e3;
  }
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank != 0 || !out) return;
  const int w = int(icetImageGetWidth(result)), h = int(icetImageGetHeight(result));
  const IceTFloat* colour = icetImageGetColorcf(result);
  out->width = w;
  out->height = h;
  out->rgba.assign(size_t(w) * size_t(h) * 4, 255);
  const glm::vec3 bg(p.background);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* c = colour + (size_t(h - 1 - y) * size_t(w) + size_t(x)) * 4;
      glm::vec3 rgb;
      if (p.mode == Mode::Dvr)
        rgb = glm::vec3(c[0], c[1], c[2]) + (1.0f - c[3]) * bg;  // as compositeParts
      else if (p.mode == Mode::Iso)
        rgb = c[3] > 0.0f ? glm::vec3(c[0], c[1], c[2]) : bg;
      else
        rgb = c[3] > 0.0f ? glm::vec3(c[0]) : bg;
      uint8_t* o = &out->rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
      o[0] = toByte(rgb.x);
      o[1] = toByte(rgb.y);
      o[2] = toByte(rgb.z);
    }
}

}  // namespace voxray::mpi
