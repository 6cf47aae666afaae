#pragma once
// File > Export movie, without Qt: the dialog's choices, the plan they make from what the
// view shows, and the export running as a BackgroundTask with progress, an estimate of the
// time left and cancel. Frames are rendered at the chosen quality preset (reference by
// default) whatever the view's interactive state: through the 3D view's renderer when the
// caller gives one (RenderWorker::renderOnDevice: the volume already on the device, no second
// upload; the view's frames go on between the movie's), else on an OpenCL context of the
// export's own.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "background_task.h"
#include "movie.h"
#include "no_qt.h"
#include "render_state_model.h"
#include "window_level.h"

namespace voxray {

struct MovieChoice {
  // 0, 1: azimuth and elevation orbits; 2, 3, 4: axial, coronal and sagittal cines.
  int kind = 0;
  // Orbit: frames over 360 degrees, turning from the view's camera; cine: slices, 0 = every
  // one. 72 at 24 fps: one turn in 3 s, 5 degrees a frame.
  int frames = 72;
  glm::ivec2 size{1024, 768};         // a cine's {0, 0}: the slice's own size
  std::string quality = "reference";  // a quality preset; empty = custom (the view's own)
  double fps = 24.0;
};

// The kinds' labels, in MovieChoice::kind order.
const std::vector<std::string>& movieKindLabels();

// The plan of CHOICE for the view's parameters and quality (planFrame, never interactive:
// the export's quality whatever the view is doing), the slice views' window and
// interpolation for a cine, settled for the format of PATH (movieFormat; throws Error
// (Output) for a path it does not take).
MoviePlan planMovie(const MovieChoice& choice, const RenderStateModel& view, const WindowLevel& wl,
                    const Volume& v, const std::string& path);

// The files of a movie of FRAMES frames at PATH that exist already (movieFiles): the user
// is asked before any of them is replaced.
std::vector<std::string> existingMovieFiles(const std::string& path, int frames);

class MovieExportTask {
 public:
  struct Events {
    std::function<void(const MovieProgress&)> progress;
    // ERROR empty: written. CANCELLED: the user stopped it (nothing was written).
    std::function<void(const std::string& error, bool cancelled)> finished;
  };
  explicit MovieExportTask(BackgroundTask::Post post = {}) : task_(std::move(post)) {}

  // Renders PLAN of VOLUME into PATH on a thread of its own; DEVICE as ClContext takes it.
  // ON_DEVICE, when set, renders the orbit's frames instead (with VOLUME on its device: no
  // context of the export's own). Ignored while an export runs.
  void start(std::shared_ptr<const Volume> volume, const std::string& device, MoviePlan plan,
             const std::string& path, MovieSettings settings, Events events,
             MovieRenderer onDevice = {});
  void cancel() { task_.cancel(); }
  bool busy() const { return busy_; }
  void wait() { task_.wait(); }

 private:
  std::atomic<bool> busy_{false};
  BackgroundTask task_;  // last member: stops before the rest goes
};

}  // namespace voxray
