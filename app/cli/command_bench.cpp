// voxray-cli bench: frames over a 360-degree orbit after a warm-up, per size x gradient
// (x kernel), reporting medians (these machines are noisy), kernel time beside wall time,
// rays and counted samples per second. --seed-table reruns the seed paper's table on the
// shared data beside its figures; --plot draws fps against resolution. --quality benches
// the workstation's own frames (a quality preset applied to the view size as the 3D view
// applies it); --stall replays the frames around the end of a drag (bench_stall.h), --drag a
// drag itself with the 3D view's frame-rate controller (bench_drag.h).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "bench_drag.h"
#include "bench_first_image.h"
#include "bench_multidev.h"
#include "bench_plot.h"
#include "bench_run.h"
#include "bench_seed.h"
#include "bench_stall.h"
#include "bench_tf_drag.h"
#include "cinematic_run.h"
#include "commands.h"
#include "input_options.h"
#include "labels_option.h"
#include "multi_device_option.h"
#include "out_of_core_run.h"
#include "overlay_option.h"
#include "quality_choice.h"
#include "render_flags.h"
#include "render_state_model.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/quality.h"
#include "voxray/io/error.h"

namespace voxray::cli {

VolumeStorage parseStorage(const std::string& s);

namespace {

struct BenchOptions {
  InputOptions input;
  RenderFlags flags;
  std::string sizes = "512x384,640x480,800x600,1024x768", gradients = "central", device;
  std::string storage = "auto", kernel = "specialised", ess = "on", local, data, plot;
  std::string orbit = "azimuth";
  std::string quality;   // a resources/quality preset: the workstation's frame at each size
  int stallRepeats = 0;  // --stall: replays of the end of a drag
  std::string drag;      // --drag: N frames of a replayed rotation, clip or clip:N
  double dragFps = Quality{}.dragFps;
  int tfDragPairs = 0;      // --tf-drag: still/moved-table frame pairs
  bool firstImage = false;  // --first-image: time to the first and the full image
  int coarseFactor = 4;
  BenchRun run;
  bool json = false, csv = false, seedTable = false, noCount = false;
  size_t slabMib = 0;
  int lanes = 0;
  CinematicFlags cinematic;
  LabelsOption labels;
  OverlayOption overlay;
  MultiDeviceOption multi;    // --split, --devices (issue 38)
  OutOfCoreOption outOfCore;  // --memory-budget (issue 38 part 2)
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

// ../shared/data beside the checkout when run from it, else the machine's shared copy.
std::string defaultDataDir() {
  for (const char* d : {"../shared/data", "/work/shared/data"})
    if (std::filesystem::is_directory(d)) return d;
  return "../shared/data";
}

RaycasterOptions raycasterOptions(const BenchOptions& o) {
  RaycasterOptions r;
  r.emptySpaceSkipping = o.ess == "on";
  r.maxSlabBytes = o.slabMib << 20;
  r.packetLanes = o.lanes;
  if (!o.local.empty()) {
    int x = 0, y = 0;
    if (std::sscanf(o.local.c_str(), "%dx%d", &x, &y) != 2 || x <= 0 || y <= 0)
      throw inputError("--local: expected WxH, e.g. 8x8, got '" + o.local + "'");
    r.localX = x;
    r.localY = y;
  }
  return r;
}

// --split / --devices: each size (and gradient) over the orbit on several devices at once.
int benchSplit(const BenchOptions& o) {
  if (o.seedTable || o.stallRepeats > 0 || !o.drag.empty() || o.tfDragPairs > 0 ||
      !o.labels.raw.empty() || !o.labels.file.empty() || !o.overlay.path.empty())
    throw inputError(
        "--split/--devices bench plain frames: leave out --seed-table, --stall, --drag, "
        "--tf-drag, --labels-raw and --overlay");
  Volume v = o.input.load();
  std::string name =
      o.input.input.empty() ? "phantom" : std::filesystem::path(o.input.input).filename().string();
  auto owned = o.multi.contexts(o.device);
  std::vector<ClContext*> contexts;
  for (auto& c : owned) contexts.push_back(c.get());
  MultiDeviceOptions mo;
  mo.emptySpaceSkipping = o.ess == "on";
  mo.budgetBytes = o.multi.budgetMib << 20;
  mo.composite = o.multi.compositeWhere();
  mo.balance = o.multi.balance;
  mo.bands = o.multi.bands;
  mo.storage = parseStorage(o.storage);
  MultiDeviceRenderer r(contexts, v, mo);
  for (const auto& size : split(o.sizes))
    for (const auto& grad : split(o.gradients)) {
      RenderParams p = o.flags.params();
      findRenderParamSpec("size").parse(p, size);
      p.gradient = parseGradient(grad);
      const glm::ivec2 view(p.width, p.height);
      if (!o.quality.empty()) p = settledFrame(p, o.quality, {0, 0}, view, v.minSpacingMm());
      MultiDeviceRow row = benchMultiDevice(r, p, o.run);
      row.input = name;
      printMultiDeviceRow(row, o.json, std::cout);
    }
  if (!o.json)
    std::printf("%d frames per case over a 360-degree orbit after a warm-up; medians\n",
                o.run.frames);
  return 0;
}

// --memory-budget: each size over the orbit out of core on one device, preview and converged.
int benchOutOfCoreSizes(const BenchOptions& o) {
  if (o.multi.active() || o.seedTable || o.stallRepeats > 0 || !o.drag.empty() ||
      o.tfDragPairs > 0 || !o.labels.raw.empty() || !o.labels.file.empty() ||
      !o.overlay.path.empty() || !o.quality.empty())
    throw inputError(
        "--memory-budget benches plain frames on one device: leave out --split/--devices, "
        "--seed-table, --stall, --drag, --tf-drag, --quality, labels and --overlay");
  std::optional<Volume> held;
  auto source = openSlabSource(o.input, held);
  const std::string name =
      o.input.input.empty() ? "phantom" : std::filesystem::path(o.input.input).filename().string();
  OutOfCoreRun run;
  run.device = o.device;
  run.storage = o.storage;
  run.ess = o.ess == "on";
  run.json = o.json;
  run.firstOnly = o.firstImage;
  for (const auto& size : split(o.sizes))
    for (const auto& grad : split(o.gradients)) {
      RenderParams p = o.flags.params();
      findRenderParamSpec("size").parse(p, size);
      p.gradient = parseGradient(grad);
      benchOutOfCore(o.outOfCore, *source, name, p, run, o.run, std::cout);
    }
  return 0;
}

}  // namespace

Run addBenchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("bench", "Frame times over an orbit (median, min, max)");
  auto o = std::make_shared<BenchOptions>();
  o->input.add(*cmd);
  cmd->add_option("--quality", o->quality,
                  "the workstation's frame of this quality preset (interactive, balanced, "
                  "reference): each --sizes is the 3D view's size, the preset sets the image "
                  "scale, step, bisections and jitter, and (unless --gradients) the gradient")
      ->check([](const std::string& s) {
        try {
          findQualityPreset(s);
          return std::string();
        } catch (const std::exception& e) {
          return std::string(e.what());
        }
      });
  cmd->add_option("--stall", o->stallRepeats,
                  "after each case, replay the end of a drag this many times: interactive drag "
                  "frames, then the --quality frame whole (the old scheduler) and in bands "
                  "(the 3D view's refinement); prints the largest gap between frames shown")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--drag", o->drag,
                  "after each case, replay a drag as the 3D view renders it (the drag preset, "
                  "sized and stepped by its frame-rate controller): N frames of a rotation, or "
                  "clip / clip:N (90 frames) of a clip-box drag, the anterior face moved to half "
                  "the volume and back; prints the settings it chose, the frame times after its "
                  "first change and whether the empty-space tables were rebuilt")
      ->check([](const std::string& s) {
        try {
          parseDragOption(s);
          return std::string();
        } catch (const std::exception& e) {
          return std::string(e.what());
        }
      });
  cmd->add_option("--tf-drag", o->tfDragPairs,
                  "pairs of frames at a still camera, the table unchanged then moved 1 HU: the "
                  "transfer-function edit's update cost (issue 35)")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--first-image", o->firstImage,
                "time from the start to the first image (a coarse level's frame) and to the "
                "full-resolution frame of the first --sizes, split by step (read, coarse level, "
                "upload, empty-space tables, frames), with the peak resident memory against "
                "the volume's bytes (issue 38); with --memory-budget: the first image alone "
                "(context, opening, frame), no converged frame");
  cmd->add_option("--coarse-factor", o->coarseFactor,
                  "--first-image: the coarse level's reduction per axis, 2, 4 or 8 (box mean); "
                  "1: no coarse frame (the full frame is the first image, as before)")
      ->check(CLI::IsMember({1, 2, 4, 8}));
  cmd->add_option("--drag-fps", o->dragFps, "the drag replay's target frame rate (the 3D view's)")
      ->check(CLI::Range(kDragFpsMin, kDragFpsMax));
  CLI::Option* gradientsOption = nullptr;
  CLI::Option* sizesOption =
      cmd->add_option("--sizes", o->sizes, "comma-separated WxH list (also for --seed-table)");
  gradientsOption = cmd->add_option("--gradients", o->gradients, "comma-separated operators");
  cmd->add_option("--frames", o->run.frames, "timed frames per case (an orbit)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--warmup", o->run.warmup, "untimed frames first (kernel build)");
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number");
  cmd->add_option("--storage", o->storage, "auto, buffer or image")
      ->check(CLI::IsMember({"auto", "buffer", "image"}));
  cmd->add_option("--kernel", o->kernel,
                  "specialised (-D per variant; on a CPU: ray packets), per-ray "
                  "(specialised, one ray per work-item), uber (runtime switches), both "
                  "(specialised and uber) or all three")
      ->check(CLI::IsMember({"specialised", "per-ray", "uber", "both", "all"}));
  cmd->add_option("--ess", o->ess, "empty-space skipping on or off")
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--local", o->local, "OpenCL work-group size WxH (default: the device's)");
  cmd->add_option("--slab-mib", o->slabMib,
                  "split the volume into z slabs of at most this many MiB on the device "
                  "(default: only when it exceeds the largest allocation)");
  cmd->add_option("--lanes", o->lanes,
                  "rays per CPU packet: 8 (4x2), 16 (4x4) or 0 (16 where the device's native "
                  "float vector holds 16, else 8)")
      ->check(CLI::IsMember({0, 8, 16}));
  cmd->add_flag("--no-count", o->noCount, "skip the extra orbit that counts samples");
  cmd->add_option("--orbit", o->orbit,
                  "azimuth (around the long axis) or elevation (around the anterior-posterior "
                  "axis from inferior: VTK's orbit of an axial stack, for the peer benchmark)")
      ->check(CLI::IsMember({"azimuth", "elevation"}));
  cmd->add_flag("--seed-table", o->seedTable,
                "the seed paper's table (Head, Brain, Stent x central, Zucker-Hummel x its "
                "four sizes) on the shared data, beside the seed's fps");
  cmd->add_option("--data", o->data, "shared data folder for --seed-table");
  cmd->add_option("--plot", o->plot, "write fps against resolution to this PNG");
  cmd->add_flag("--json", o->json, "machine-readable output");
  cmd->add_flag("--csv", o->csv, "CSV output");
  o->flags.add(*cmd, {"size", "gradient", "azimuth"});
  o->cinematic.add(*cmd);
  o->labels.add(*cmd);
  o->overlay.add(*cmd);
  o->multi.add(*cmd);
  o->outOfCore.add(*cmd);
  return [o, sizesOption, gradientsOption] {
    if (o->stallRepeats > 0 && o->quality.empty())
      throw inputError("--stall needs --quality (the sharp frame's preset, e.g. balanced)");
    if (!o->quality.empty() && gradientsOption->count() == 0)
      o->gradients = toString(findQualityPreset(o->quality).gradient);
    BenchFormat f = o->json ? BenchFormat::Json : o->csv ? BenchFormat::Csv : BenchFormat::Text;
    o->run.countSamples = !o->noCount;
    o->run.orbit = o->orbit == "elevation" ? Orbit::Elevation : Orbit::Azimuth;
    if (o->multi.active()) return benchSplit(*o);
    if (o->outOfCore.active()) return benchOutOfCoreSizes(*o);
    if (o->firstImage) {
      RenderParams p = o->flags.params();
      findRenderParamSpec("size").parse(p, split(o->sizes).front());
      p.gradient = parseGradient(split(o->gradients).front());
      FirstImageOptions fo;
      fo.coarseFactor = o->coarseFactor;
      fo.device = o->device;
      fo.storage = o->storage;
      fo.json = o->json;
      return benchFirstImage(o->input, p, fo, std::cout);
    }
    ClContext ctx(o->device);
    std::vector<std::string> kernels = {o->kernel};
    if (o->kernel == "both") kernels = {"specialised", "uber"};
    if (o->kernel == "all") kernels = {"specialised", "per-ray", "uber"};
    std::vector<BenchRow> rows;
    printHeader(f);
    // One volume: each size x gradient x kernel, seed figures filled in by the caller.
    auto bench = [&](const Volume& v, RenderParams base, const std::string& name,
                     const std::vector<std::string>& sizes, const std::vector<std::string>& grads,
                     const double* seedCentral, const double* seedZucker) {
      Raycaster rc(ctx, v, parseStorage(o->storage));
      if (auto seg = o->labels.load(v)) rc.setSegmentation(*seg);
      const auto overlay = o->overlay.load(v);  // fused dvr (issue 36): copied to the device
      if (overlay)
        for (const std::string& w : rc.setOverlay(overlay->first, overlay->second))
          std::cerr << "voxray-cli: warning: --overlay: " << w << "\n";
      for (size_t si = 0; si < sizes.size(); ++si)
        for (const auto& grad : grads)
          for (const auto& kern : kernels) {
            RenderParams p = base;
            findRenderParamSpec("size").parse(p, sizes[si]);
            p.gradient = parseGradient(grad);
            // The 3D view's frame at rest at this view size (RenderScheduler::fullParams).
            const glm::ivec2 view(p.width, p.height);
            if (!o->quality.empty())
              p = settledFrame(p, o->quality, {0, 0}, view, v.minSpacingMm());
            RaycasterOptions ro = raycasterOptions(*o);
            ro.kernel = kern == "uber" ? RaycasterOptions::Kernel::Uber
                                       : RaycasterOptions::Kernel::Specialised;
            ro.packets = kern != "per-ray";
            rc.setOptions(ro);
            rc.setPathTracerOptions(o->cinematic.tracer);  // a progressive case starts afresh
            Renderer& renderer = rc.rendererFor(p);
            BenchRow r = renderer.progressive() ? benchPasses(renderer, p, o->run)
                                                : benchCase(rc, p, o->run);
            r.input = name;
            if (rc.slabCount() > 1) r.input += "/" + std::to_string(rc.slabCount()) + "slabs";
            const double* seed = p.gradient == Gradient::Central        ? seedCentral
                                 : p.gradient == Gradient::ZuckerHummel ? seedZucker
                                                                        : nullptr;
            for (int k = 0; seed && k < 4; ++k)
              if (sizes[si] == kSeedSizes[k]) r.seedFps = seed[k];
            printRow(f, r);
            rows.push_back(r);
            if (o->stallRepeats > 0) {
              // The drag frame as the scheduler plans it before AdaptiveQuality moves it.
              RenderParams drag =
                  settledFrame(base, kDragQualityPreset, {0, 0}, view, v.minSpacingMm());
              drag.gradient = p.gradient;
              printStallReplay(rc, drag, p, o->run.orbit, o->stallRepeats);
            }
            if (o->tfDragPairs > 0) printTfDrag(replayTfDrag(rc, p, o->tfDragPairs));
            if (!o->drag.empty()) {
              RenderParams b = base;
              b.gradient = p.gradient;
              const DragOption drag = parseDragOption(o->drag);
              printDragReplay(replayDrag(rc, b, view, v.minSpacingMm(), o->run.orbit, drag.frames,
                                         o->dragFps, drag.motion),
                              o->dragFps);
            }
          }
    };
    if (o->seedTable) {
      std::string dir = o->data.empty() ? defaultDataDir() : o->data;
      for (const auto& d : seedDatasets(dir)) {
        Volume v = d.input.load();
        RenderParams p = o->flags.params();
        p.mode = Mode::Iso;
        p.isoLo = d.isoHu;
        std::vector<std::string> sizes(std::begin(kSeedSizes), std::end(kSeedSizes));
        if (sizesOption->count() > 0) sizes = split(o->sizes);
        bench(v, p, d.name, sizes, {"central", "zucker-hummel"}, d.seedCentral, d.seedZucker);
      }
      if (f == BenchFormat::Text)
        std::cout << "Bunny: no data here (the seed's row is left out). Stent spacing "
                     "assumed 1 x 1 x 1 mm.\n";
    } else {
      Volume v = o->input.load();
      std::string name = o->input.input.empty()
                             ? "phantom"
                             : std::filesystem::path(o->input.input).filename().string();
      bench(v, o->flags.params(), name, split(o->sizes), split(o->gradients), nullptr, nullptr);
    }
    printFooter(f, rows, ctx.device().name, o->run.frames);
    if (!o->plot.empty()) writeBenchPlot(o->plot, rows);
    return 0;
  };
}

}  // namespace voxray::cli
