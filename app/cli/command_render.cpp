#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

#include "cinematic_run.h"
#include "commands.h"
#include "input_options.h"
#include "labels_option.h"
#include "multi_device_option.h"
#include "out_of_core_run.h"
#include "overlay_option.h"
#include "render_flags.h"
#include "render_state_model.h"
#include "session.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/multi_device.h"
#include "voxray/engine/quality.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/error.h"
#include "voxray/io/secondary_capture.h"

namespace voxray::cli {

namespace {
struct RenderOptions {
  InputOptions input;
  RenderFlags flags;
  std::string output, device, storage = "auto";
  size_t slabMib = 0;
  int repeat = 0;          // timed frames after the first (a still camera's frame time)
  bool reference = false;  // the double-precision host renderer instead of OpenCL
  std::string session, quality, saveSession;
  bool force = false;
  CinematicFlags cinematic;
  LabelsOption labels;
  OverlayOption overlay;
  MultiDeviceOption multi;    // --split, --devices (issue 38)
  OutOfCoreOption outOfCore;  // --memory-budget (issue 38 part 2)
};

// What this command line renders: the session's state (when --session is given) with what
// was given here on top. INPUT, input flags, --quality and render flags win over the session.
// --quality is picked as the workstation's quality box picks it (pickQualityPreset: its
// reconstruction and gradient), before the render flags, so that --interp or --gradient
// given with it win as the Rendering group's do after a pick.
Session sessionToRender(const RenderOptions& o) {
  Session s;
  s.qualityPreset.clear();  // no session: the parameters as given (custom)
  if (!o.session.empty()) {
    SessionRead read = readSessionFile(o.session);
    for (const auto& w : read.warnings)
      std::cerr << "voxray-cli: warning: session " << o.session << ": " << w << "\n";
    if (o.input.input.empty() && !read.missingInput.empty())
      throw inputError(movedDataMessage(
          o.session, read.missingInput,
          "Move it back, or give its new location as INPUT: voxray-cli render NEW_LOCATION "
          "--session " +
              o.session + " -o " + o.output));
    s = std::move(read.session);
  }
  if (!o.input.input.empty()) s.input.path = o.input.input;
  for (const auto& [key, value] : o.input.flags) s.input.flags[key] = value;
  if (!o.quality.empty()) {
    const QualityPreset& q = findQualityPreset(o.quality);
    s.qualityPreset = q.name;
    s.render = pickQualityPreset(s.render, q);
  }
  o.flags.applyTo(s.render);
  return s;
}

// The frame to render: with a session or --quality, the workstation's view at rest
// (planFrame); the size is --size when given, else the session's view size at its
// quality's image scale, else the default.
RenderParams frameToRender(const RenderOptions& o, const Session& s, const Volume& v) {
  if (o.session.empty() && o.quality.empty()) return s.render;
  Quality q;
  q.preset = s.qualityPreset;
  q.resolution = s.resolution;
  RenderParams p =
      planFrame(s.render, q, {s.render.width, s.render.height}, false, v.minSpacingMm());
  if (o.session.empty() || o.flags.given.count("size")) {
    p.width = s.render.width;
    p.height = s.render.height;
  }
  return p;
}
}  // namespace

VolumeStorage parseStorage(const std::string& s) {
  return s == "buffer"  ? VolumeStorage::Buffer
         : s == "image" ? VolumeStorage::Image3d
                        : VolumeStorage::Auto;
}

namespace {
// PNG, TIFF or EXR; or, for a .dcm name, a DICOM Secondary Capture in the volume's study.
void writeRenderOutput(const std::string& path, const Image& img, const Volume& v) {
#ifdef VOXRAY_HAS_DICOM
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".dcm") == 0) {
    SecondaryCaptureInfo info;
    info.study = v.study;
    writeSecondaryCapture(path, {img}, info);
    return;
  }
#else
  (void)v;  // a build without DICOM writes no Secondary Capture
#endif
  writeImage(path, img);
}
// --split / --devices: the frame on several devices, composited (sort-last).
int renderSplit(const RenderOptions& o, const Volume& v, const RenderParams& p) {
  if (!o.labels.raw.empty() || !o.labels.file.empty() || !o.overlay.path.empty())
    throw inputError("--split/--devices render without labels or an overlay: leave them out");
  auto owned = o.multi.contexts(o.device);
  std::vector<ClContext*> contexts;
  for (auto& c : owned) contexts.push_back(c.get());
  MultiDeviceOptions mo;
  mo.budgetBytes = o.multi.budgetMib << 20;
  mo.composite = o.multi.compositeWhere();
  mo.balance = o.multi.balance;
  mo.bands = o.multi.bands;
  mo.storage = parseStorage(o.storage);
  MultiDeviceRenderer r(contexts, v, mo);
  MultiDeviceStats stats;
  Image img = r.render(p, &stats);
  writeRenderOutput(o.output, img, v);
  std::cerr << "rendered " << p.width << "x" << p.height << " " << toString(p.mode) << " on "
            << stats.parts.size() << " devices in " << stats.totalMs
            << " ms (first frame includes the kernel builds; composite " << stats.compositeMs
            << " ms)\n";
  for (size_t k = 0; k < stats.parts.size(); ++k) {
    const PartStats& d = stats.parts[k];
    std::cerr << "  device " << k + 1 << ": " << d.device << ", slices " << d.range.first << "-"
              << d.range.end - 1 << ", kernel " << d.kernelMs << " ms\n";
  }
  std::cerr << "-> " << o.output << "\n";
  return 0;
}

// --reference: the host renderer has no labels, overlay, devices or path tracer to offer.
int renderWithReference(const RenderOptions& o, const Volume& v, const RenderParams& p) {
  if (!o.labels.raw.empty() || !o.labels.file.empty() || !o.overlay.path.empty() ||
      o.multi.active() || o.repeat > 0 || p.lighting != Lighting::Phong)
    throw inputError(
        "--reference renders phong lighting alone: leave out labels, --overlay, --split, "
        "--devices, --repeat and --lighting other than phong");
  const auto t0 = std::chrono::steady_clock::now();
  Image img = renderReference(v, p);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  writeRenderOutput(o.output, img, v);
  std::cerr << "rendered " << p.width << "x" << p.height << " " << toString(p.mode)
            << " with the double-precision reference renderer in " << ms << " ms -> " << o.output
            << "\n";
  return 0;
}

// --repeat N: wall time of each whole frame (kernel, read-back, any per-frame tables) at
// the still camera; stdout, so that scripts can read it apart from the log.
void printRepeatedFrames(Renderer& r, const RenderParams& p, const RenderOptions& o) {
  std::vector<double> ms;
  Image img;
  for (int i = 0; i < o.repeat; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    r.renderStill(p, o.cinematic.budget(), img, nullptr);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  std::printf("frames %d ms median %.3f min %.3f max %.3f each", o.repeat, median, sorted.front(),
              sorted.back());
  for (double t : ms) std::printf(" %.3f", t);
  std::printf("\n");
}

}  // namespace

Run addRenderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render", "Render a volume to an image (PNG, TIFF, EXR; .dcm: DICOM Secondary Capture)");
  auto o = std::make_shared<RenderOptions>();
  o->input.add(*cmd);
  cmd->add_option("-o,--output", o->output, "image file to write (.dcm: DICOM SC)")->required();
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number ($VOXRAY_DEVICE)");
  cmd->add_option("--storage", o->storage, "volume on the device: auto, buffer or image")
      ->check(CLI::IsMember({"auto", "buffer", "image"}));
  cmd->add_option("--slab-mib", o->slabMib,
                  "split the volume into z slabs of at most this many MiB on the device "
                  "(default: only when it exceeds the largest allocation)");
  cmd->add_option("--session", o->session,
                  "render a saved session's 3D view: its input, parameters, view size and "
                  "quality; INPUT, input flags, --quality and render flags given here win");
  cmd->add_option("--quality", o->quality,
                  "quality preset: interactive, balanced or reference, picked as the "
                  "workstation's quality box does (its reconstruction and gradient; --interp "
                  "and --gradient given win) and rendered as its view at rest (its step, "
                  "refinement and jitter) (default: the session's; none without a session)");
  cmd->add_option("--save-session", o->saveSession,
                  "also save this render's input, parameters and quality as a session file");
  cmd->add_flag("--force", o->force, "--save-session may replace an existing file");
  cmd->add_option("--repeat", o->repeat,
                  "render the frame N more times at the still camera and print the median wall "
                  "time of those (the first frame builds the kernels, so it is left out)")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--reference", o->reference,
                "render with the double-precision host reference renderer (the accuracy "
                "sweep's ground truth: the kernels' maths without OpenCL; slow) instead");
  o->flags.add(*cmd);
  o->cinematic.add(*cmd);
  o->labels.add(*cmd);
  o->overlay.add(*cmd);
  o->multi.add(*cmd);
  o->outOfCore.add(*cmd);
  return [o] {
    const Session s = sessionToRender(*o);
    InputOptions input = o->input;
    input.input = s.input.path;
    input.flags = s.input.flags;
    if (o->outOfCore.active()) {
      if (o->reference || o->multi.active() || !o->labels.raw.empty() || !o->labels.file.empty() ||
          !o->overlay.path.empty() || !o->saveSession.empty() || o->repeat > 0)
        throw inputError(
            "--memory-budget renders plain frames on one device: leave out --reference, "
            "--split/--devices, labels, --overlay, --save-session and --repeat");
      std::optional<Volume> held;  // the loaded volume, when INPUT is not streamed
      auto source = openSlabSource(input, held);
      OutOfCoreRun run;
      run.device = o->device;
      run.storage = o->storage;
      return renderOutOfCore(o->outOfCore, *source, frameToRender(*o, s, source->geometry()), run,
                             o->output);
    }
    Volume v = input.load();
    const RenderParams p = frameToRender(*o, s, v);
    if (!o->saveSession.empty()) {  // before rendering: a kept file stops the command early
      Session saved = s;
      saved.crosshair = v.dims / 2;  // the slice views at the centre, as a study opens
      writeSessionFile(o->saveSession, saved, o->force);
      std::cerr << "session saved -> " << o->saveSession << "\n";
    }
    if (o->reference) return renderWithReference(*o, v, p);
    if (o->multi.active()) return renderSplit(*o, v, p);
    ClContext ctx(o->device);
    Raycaster rc(ctx, v, parseStorage(o->storage));
    RaycasterOptions ro;
    ro.maxSlabBytes = o->slabMib << 20;
    rc.setOptions(ro);
    rc.setPathTracerOptions(o->cinematic.tracer);
    if (auto seg = o->labels.load(v)) rc.setSegmentation(*seg);
    const auto overlay = o->overlay.load(v);  // fused dvr (issue 36): copied to the device
    if (overlay) {
      for (const std::string& w : rc.setOverlay(overlay->first, overlay->second))
        std::cerr << "voxray-cli: warning: --overlay: " << w << "\n";
      if (p.mode == Mode::Iso)
        std::cerr << "voxray-cli: warning: --overlay is fused into dvr and mip frames only; "
                     "this frame is "
                  << toString(p.mode) << "\n";
    }
    FrameStats stats;
    Image img;
    rc.rendererFor(p).renderStill(p, o->cinematic.budget(), img, &stats);
    logPathRun(stats, o->cinematic, std::cerr);
    writeRenderOutput(o->output, img, v);
    std::cerr << "rendered " << p.width << "x" << p.height << " " << toString(p.mode) << " on "
              << ctx.device().name << " in " << stats.totalMs << " ms (kernel " << stats.kernelMs
              << " ms, first frame includes the kernel build";
    if (stats.lightingMs > 0.0)  // shadows, ao: the light grid, inside the total
      std::cerr << "; " << toString(p.lighting) << " precomputation " << stats.lightingMs << " ms";
    if (rc.slabCount() > 1) std::cerr << "; " << rc.slabCount() << " z slabs";
    if (stats.adaptiveBlocks > 0)  // --adaptive-image
      std::cerr << "; adaptive image: " << stats.adaptiveRefined << " of " << stats.adaptiveBlocks
                << " blocks refined";
    std::cerr << ") -> " << o->output << "\n";
    if (o->repeat > 0) printRepeatedFrames(rc.rendererFor(p), p, *o);
    return 0;
  };
}

}  // namespace voxray::cli
