// voxray-cli movie: a 360-degree orbit of the 3D view, or a cine through the slices of one
// MPR view, as MP4 (H.264) or PNG frames. Frames are rendered and written one at a time;
// Ctrl-C stops after the frame in progress and leaves nothing under the output's name.
#include <atomic>
#include <csignal>
#include <iostream>

#include "commands.h"
#include "existing_output.h"
#include "input_options.h"
#include "movie.h"
#include "progress.h"
#include "render_flags.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/quality.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/volume.h"
#ifdef VOXRAY_HAS_DICOM  // the PACS client's library, which reads OME-Zarr URLs too
#include "voxray/io/zarr_url.h"
#endif

namespace voxray::cli {

namespace {

struct MovieOptions {
  InputOptions input;
  RenderFlags flags;
  std::string output, device, orbit, cine, quality = "reference";
  int frames = -1;  // -1: 36 for an orbit, every slice for a cine
  MovieSettings settings;
  bool overwrite = false;
};

std::atomic<bool> interrupted{false};

void onInterrupt(int) { interrupted = true; }

// The first Ctrl-C (or TERM) asks the loop to stop; SA_RESETHAND: a second one kills.
void catchInterrupts() {
  struct sigaction action = {};
  action.sa_handler = onInterrupt;
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

MoviePlan plan(const MovieOptions& o, const Volume& v) {
  MoviePlan plan;
  plan.cine = !o.cine.empty();
  plan.orbit = o.orbit == "elevation" ? Orbit::Elevation : Orbit::Azimuth;
  plan.view = o.cine == "coronal"    ? Orientation::Coronal
              : o.cine == "sagittal" ? Orientation::Sagittal
                                     : Orientation::Axial;
  plan.frames = o.frames >= 0 ? o.frames : plan.cine ? 0 : 36;
  // The quality preset first, then every flag given: what the user wrote wins.
  RenderParams p;
  if (o.quality != "custom") p = applyQuality(p, findQualityPreset(o.quality), v);
  o.flags.applyTo(p);
  if (plan.cine && !o.flags.given.count("size")) p.width = p.height = 0;  // the slice's own
  if (!plan.cine && !o.flags.given.count("size")) {
    p.width = 1024;
    p.height = 768;
  }
  plan.params = p;
  // A cine's window is --window, the flag that sets mip's grey window.
  if (plan.cine) plan.window = {p.windowWidth, p.windowLevel};
  return plan;
}

}  // namespace

Run addMovieCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("movie",
                                 "A 360-degree orbit or a slice cine as MP4 (H.264) or PNG frames");
  auto o = std::make_shared<MovieOptions>();
  o->input.add(*cmd);
  cmd->add_option("-o,--output", o->output,
                  "out.mp4, a folder for PNG frames (frames/), or a pattern (frames/%04d.png)")
      ->required();
  auto* orbit = cmd->add_option("--orbit", o->orbit,
                                "azimuth (around the long axis, from anterior; the default) or "
                                "elevation (over the top): the orbit of `bench --orbit`")
                    ->check(CLI::IsMember({"azimuth", "elevation"}));
  cmd->add_option("--cine", o->cine,
                  "a cine through the slices of one MPR view instead, or `time`: the axial "
                  "middle slice over every time point of a 4D series")
      ->check(CLI::IsMember({"axial", "coronal", "sagittal", "time"}))
      ->excludes(orbit);
  cmd->add_option("--frames", o->frames,
                  "orbit: frames over 360 degrees (default 36); cine: slices, spread evenly "
                  "(default: every slice)")
      ->check(CLI::Range(0, 100000));
  cmd->add_option("--quality", o->quality,
                  "quality preset (resources/quality): interactive, balanced, reference, or "
                  "custom (the render flags' own step, gradient and refinement); flags given "
                  "win over the preset")
      ->check(CLI::IsMember({"interactive", "balanced", "reference", "custom"}));
  cmd->add_option("--fps", o->settings.fps, "frames per second of the MP4")
      ->check(CLI::Range(1.0, 120.0));
  cmd->add_option("--crf", o->settings.crf,
                  "H.264 constant rate factor: 0 lossless ... 51 worst (default 18)")
      ->check(CLI::Range(0, 51));
  cmd->add_flag("--overwrite", o->overwrite, "replace an existing movie or frames");
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number ($VOXRAY_DEVICE)");
  o->flags.add(*cmd);
  return [o] {
    const MovieFormat format = movieFormat(o->output);
    std::vector<Volume> times;  // --cine time: every time point
    if (o->cine == "time") {
      if (o->input.flags.count("time"))
        throw inputError("movie: --cine time shows every time point; leave out --time");
#ifdef VOXRAY_HAS_DICOM
      times = loadVolumeSeriesOrUrl(o->input.input, o->input.loadOptions());
#else
      times = loadVolumeSeries(o->input.input, o->input.loadOptions());
#endif
    }
    Volume v = times.empty() ? o->input.load() : Volume{};
    const Volume& shown = times.empty() ? v : times.front();
    MoviePlan p = plan(*o, shown);
    if (!times.empty()) p.timePoints = &times;
    const MovieSize asked = settleMovieSize(p, shown, format);
    if (asked.width != p.params.width || asked.height != p.params.height) {
      std::cerr << "note: H.264 (4:2:0) needs an even width and height: frames are "
                << p.params.width << "x" << p.params.height << ", not " << asked.width << "x"
                << asked.height << "\n";
    }
    std::unique_ptr<ClContext> ctx;
    if (!p.cine) ctx = std::make_unique<ClContext>(o->device);
    MovieFrames frames(shown, ctx.get(), p);
    for (const auto& file : movieFiles(o->output, frames.count()))
      refuseExisting(file, o->overwrite, "--overwrite");
    auto bar = terminalProgress("movie");
    catchInterrupts();
    MovieProgress last;
    double firstS = 0.0;  // the first frame, with the kernel build
    try {
      writeMovie(
          frames, o->output, o->settings,
          [&](const MovieProgress& at) {
            last = at;
            if (at.done == 1) firstS = at.elapsedS;
            if (bar && at.done > 0) bar(double(at.done) / at.total, describeProgress(at));
          },
          &interrupted);
    } catch (const Error& e) {
      if (e.kind() != Error::Kind::Cancelled) throw;
      std::cerr << "voxray-cli: movie cancelled after " << last.done << " of " << last.total
                << " frames; nothing was written to " << o->output << "\n";
      return 130;
    }
    std::cerr << "wrote " << last.total << " frames of " << p.params.width << "x" << p.params.height
              << " in " << last.elapsedS << " s";
    if (!p.cine && last.total > 1) {
      std::cerr << " (the first " << firstS << " s with the kernel build, then "
                << (last.elapsedS - firstS) / (last.total - 1) << " s per frame)";
    } else {
      std::cerr << " (" << last.elapsedS / last.total << " s per frame)";
    }
    std::cerr << " -> " << o->output << "\n";
    return 0;
  };
}

}  // namespace voxray::cli
