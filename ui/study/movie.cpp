#include "movie.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

// The slice a cine shows as frame K: FRAMES spread evenly over the first to the last slice.
int cineSlice(int k, int frames, int slices) {
  if (frames <= 1) return (slices - 1) / 2;
  return int(std::lround(double(k) * (slices - 1) / (frames - 1)));
}

}  // namespace

MovieSize settleMovieSize(MoviePlan& plan, const Volume& v, MovieFormat format) {
  RenderParams& p = plan.params;
  if (plan.cine && (p.width <= 0 || p.height <= 0)) {
    const glm::ivec2 own = cinePlane(v, plan.view, 0, {0, 0}).size;
    p.width = own.x;
    p.height = own.y;
  }
  const MovieSize asked{p.width, p.height};
  const MovieSize stored = movieFrameSize(format, asked);
  p.width = stored.width;
  p.height = stored.height;
  return asked;
}

int movieFrameCount(const MoviePlan& plan, const Volume& v) {
  if (plan.cine && plan.timePoints) return int(plan.timePoints->size());
  if (plan.frames > 0 || !plan.cine) return plan.frames;
  return cineSliceCount(v, plan.view);
}

MovieFrames::MovieFrames(const Volume& v, ClContext* ctx, MoviePlan plan)
    : MovieFrames(v, ctx, MovieRenderer{}, std::move(plan)) {}

MovieFrames::MovieFrames(const Volume& v, MoviePlan plan, MovieRenderer render)
    : MovieFrames(v, nullptr, std::move(render), std::move(plan)) {}

MovieFrames::MovieFrames(const Volume& v, ClContext* ctx, MovieRenderer render, MoviePlan plan)
    : v_(v), plan_(std::move(plan)), render_(std::move(render)) {
  if (v.voxelCount() == 0) throw inputError("the volume is empty: there is nothing to film");
  const int slices = plan_.cine ? cineSliceCount(v, plan_.view) : 0;
  count_ = movieFrameCount(plan_, v);
  if (count_ <= 0) throw inputError("--frames: an orbit needs at least one frame");
  if (plan_.cine && plan_.timePoints) {
    for (const Volume& t : *plan_.timePoints)
      if (t.dims != v.dims)
        throw inputError("the time points differ in size: a cine over time needs one grid");
  } else if (plan_.cine && count_ > slices) {
    throw inputError("--frames: this view has " + std::to_string(slices) +
                     " slices; ask for at most that many (or 0 for every slice)");
  }
  if (plan_.params.width <= 0 || plan_.params.height <= 0)
    throw inputError("--size: a movie needs a frame size such as 1024x768");
  if (!plan_.cine && !render_) {
    if (!ctx) throw Error(Error::Kind::Internal, "an orbit movie needs an OpenCL context");
    raycaster_ = std::make_unique<Raycaster>(*ctx, v);
  }
}

MovieFrames::~MovieFrames() = default;

MovieSize MovieFrames::size() const { return {plan_.params.width, plan_.params.height}; }

CameraParams orbitFrameCamera(const MoviePlan& plan, int frame, int frames) {
  CameraParams c = plan.params.camera;
  if (!plan.orbitFromView) {
    orbitCamera(c, plan.orbit, frame, frames);
    return c;
  }
  const double turn = 360.0 * frame / frames;
  if (plan.orbit == Orbit::Azimuth)
    c.azimuthDeg += turn;
  else
    c.elevationDeg += turn;  // past 90 the camera looks from behind, upside down: a tumble
  return c;
}

RenderParams MovieFrames::params(int k) const {
  RenderParams p = plan_.params;
  if (!plan_.cine) p.camera = orbitFrameCamera(plan_, k, count_);
  return p;
}

Image MovieFrames::frame(int k) {
  const RenderParams p = params(k);
  if (!plan_.cine) return render_ ? render_(p) : raycaster_->rendererFor(p).render(p);
  // Over time: time point K at the middle slice; else slice K of the one volume.
  const Volume& v = plan_.timePoints ? (*plan_.timePoints)[size_t(k)] : v_;
  const int slices = cineSliceCount(v, plan_.view);
  const int slice = plan_.timePoints ? (slices - 1) / 2 : cineSlice(k, count_, slices);
  const PlaneGrid g = cinePlane(v, plan_.view, slice, {p.width, p.height});
  // Outside the slice (the margins of another aspect ratio): black.
  const std::vector<float> values =
      samplePlane(v, g, p.interp, std::numeric_limits<float>::lowest());
  const WindowLevel& wl = plan_.window;
  double width = wl.width, lo = wl.level - 0.5 * wl.width;
  if (width <= 0.0) {  // the whole range (of every time point), as mip's window
    double a = std::numeric_limits<double>::max(), b = std::numeric_limits<double>::lowest();
    auto widen = [&](const Volume& each) {
      const ValueRange r = storedRange(each);
      const double x = each.toPhysical(r.min), y = each.toPhysical(r.max);
      a = std::min({a, x, y});
      b = std::max({b, x, y});
    };
    if (plan_.timePoints)
      for (const Volume& t : *plan_.timePoints) widen(t);
    else
      widen(v_);
    lo = a;
    width = std::max(b - a, 1e-6);
  }
  Image img(g.size.x, g.size.y);
  for (size_t i = 0; i < values.size(); ++i) {
    uint8_t* q = &img.rgba[i * 4];
    q[0] = q[1] = q[2] = greyRamp(values[i], lo, width);
    q[3] = 255;
  }
  return img;
}

std::string describeProgress(const MovieProgress& p) {
  std::string text = "frame " + std::to_string(p.done) + " of " + std::to_string(p.total);
  if (p.done == 0 || p.done >= p.total) return text;
  const int s = int(std::lround(p.leftS));
  text += ", about ";
  if (s >= 60) text += std::to_string(s / 60) + " min ";
  return text + std::to_string(s % 60) + " s left";
}

void writeMovie(MovieFrames& frames, const std::string& path, const MovieSettings& settings,
                const std::function<void(const MovieProgress&)>& progress,
                const std::atomic<bool>* cancel) {
  MovieSettings s = settings;
  s.size = frames.size();
  s.frames = frames.count();
  std::unique_ptr<MovieWriter> writer = openMovieWriter(path, s);
  const auto start = std::chrono::steady_clock::now();
  MovieProgress at{0, s.frames, 0.0, 0.0};
  if (progress) progress(at);
  for (int k = 0; k < s.frames; ++k) {
    if (cancel && *cancel) throw cancelledError("movie export cancelled");
    writer->push(frames.frame(k));
    at.done = k + 1;
    at.elapsedS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    at.leftS = at.elapsedS / at.done * (at.total - at.done);
    if (progress) progress(at);
  }
  if (cancel && *cancel) throw cancelledError("movie export cancelled");
  writer->finish();
}

}  // namespace voxray
