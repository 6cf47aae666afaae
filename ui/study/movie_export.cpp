#include "movie_export.h"

#include <algorithm>
#include <filesystem>

#include "voxray/engine/cl_context.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

const std::vector<std::string>& movieKindLabels() {
  static const std::vector<std::string> labels = {
      "Orbit around the long axis (azimuth)", "Orbit over the top (elevation)",
      "Cine through the axial slices", "Cine through the coronal slices",
      "Cine through the sagittal slices"};
  return labels;
}

MoviePlan planMovie(const MovieChoice& choice, const RenderStateModel& view, const WindowLevel& wl,
                    const Volume& v, const std::string& path) {
  MoviePlan plan;
  plan.cine = choice.kind >= 2;
  plan.orbit = choice.kind == 1 ? Orbit::Elevation : Orbit::Azimuth;
  plan.view = choice.kind == 3   ? Orientation::Coronal
              : choice.kind == 4 ? Orientation::Sagittal
                                 : Orientation::Axial;
  plan.frames = choice.frames;
  plan.orbitFromView = true;  // the movie turns the view the user looks at
  Quality q = view.quality();
  q.preset = choice.quality;
  q.resolution = choice.size;
  const double minSpacing = v.minSpacingMm();
  plan.params = planFrame(view.params(), q, choice.size, false, minSpacing);
  plan.params.width = choice.size.x;  // exactly the size asked for (planFrame keeps >= 16)
  plan.params.height = choice.size.y;
  if (plan.cine) {  // as the slice views show it
    plan.window = wl;
    plan.params.interp = view.sliceInterp();
  }
  settleMovieSize(plan, v, movieFormat(path));
  return plan;
}

std::vector<std::string> existingMovieFiles(const std::string& path, int frames) {
  std::vector<std::string> existing;
  std::error_code ec;
  for (const auto& file : movieFiles(path, frames))  // a folder or a dangling link counts too
    if (std::filesystem::exists(std::filesystem::symlink_status(file, ec)))
      existing.push_back(file);
  return existing;
}

void MovieExportTask::start(std::shared_ptr<const Volume> volume, const std::string& device,
                            MoviePlan plan, const std::string& path, MovieSettings settings,
                            Events events, MovieRenderer onDevice) {
  if (busy_.exchange(true)) return;
  task_.start([this, volume, device, plan, path, settings, events, onDevice] {
    std::string error;
    bool cancelled = false;
    try {
      std::unique_ptr<ClContext> ctx;
      if (!plan.cine && !onDevice) ctx = std::make_unique<ClContext>(device);
      std::unique_ptr<MovieFrames> made =
          onDevice ? std::make_unique<MovieFrames>(*volume, plan, onDevice)
                   : std::make_unique<MovieFrames>(*volume, ctx.get(), plan);
      MovieFrames& frames = *made;
      writeMovie(
          frames, path, settings,
          [&](const MovieProgress& p) {
            if (events.progress) task_.post([f = events.progress, p] { f(p); });
          },
          task_.cancelFlag());
    } catch (const std::exception& e) {
      cancelled = isCancellation(e);
      error = e.what();
    }
    cancelled = cancelled || task_.cancelled();
    busy_ = false;
    if (events.finished)
      task_.post([f = events.finished, error, cancelled] { f(cancelled ? "" : error, cancelled); });
  });
}

}  // namespace voxray
