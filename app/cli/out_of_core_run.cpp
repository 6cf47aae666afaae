#include "out_of_core_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "voxray/engine/cl_context.h"
#include "voxray/engine/orbit.h"
#include "voxray/engine/out_of_core.h"
#include "voxray/io/error.h"
#include "voxray/io/image.h"
#include "voxray/io/raw_import.h"
#include "voxray/io/statistics.h"
#ifdef VOXRAY_HAS_ZARR
#include "voxray/io/ome_zarr.h"
#endif

namespace voxray::cli {

VolumeStorage parseStorage(const std::string& s);

void OutOfCoreOption::add(CLI::App& cmd) {
  cmd.add_option("--memory-budget", budgetMib,
                 "render out of core on one device holding at most MIB of the volume (its "
                 "parts, coarse level and empty-space cells): the rest is uploaded part by part "
                 "as each frame needs it; an OME-Zarr or raw INPUT is read on demand, never "
                 "whole")
      ->check(CLI::Range(size_t(1), size_t(1) << 30));
  cmd.add_option("--part-slices", partSlices,
                 "with --memory-budget: slices each part owns (default: about 8 parts fit)")
      ->check(CLI::Range(1, 1 << 20));
  cmd.add_option("--ooc-upload", upload,
                 "with --memory-budget: how parts reach the device: pinned (host staging the "
                 "runtime pins, copies on a queue of their own beside the kernels), direct (the "
                 "slices where they are, a blocking copy) or auto (pinned on a GPU, direct on a "
                 "CPU)")
      ->check(CLI::IsMember({"auto", "direct", "pinned"}));
  cmd.add_option("--ooc-reuse", reuse,
                 "with --memory-budget and pinned uploads: on (default) copies a part into an "
                 "evicted part's device memory of its size; off releases and allocates per part "
                 "(for comparing the two)")
      ->check(CLI::IsMember({"on", "off"}));
}

std::unique_ptr<SlabSource> openSlabSource(const InputOptions& input, std::optional<Volume>& held) {
#ifdef VOXRAY_HAS_ZARR
  if (!input.input.empty() && isOmeZarr(input.input)) {
    if (input.level != 0 || !input.flags.empty())
      throw inputError(
          "--memory-budget streams an OME-Zarr's full-resolution level as it is: "
          "leave out --level and the input flags");
    return omeZarrSlabSource(input.input);
  }
#endif
  // A raw input is read with pread a range of slices at a time, never whole.
  const LoadOptions o = input.loadOptions();
  if (o.raw && !input.input.empty() && input.input.rfind("db:", 0) != 0)
    return rawSlabSource(input.input, *o.raw);
  held = input.load();
  return volumeSlabSource(*held);
}

namespace {

OutOfCoreOptions optionsOf(const OutOfCoreOption& option, const OutOfCoreRun& run) {
  OutOfCoreOptions o;
  o.budgetBytes = option.budgetMib << 20;
  o.partSlices = option.partSlices;
  o.upload = option.upload == "pinned"   ? OutOfCoreOptions::Upload::Pinned
             : option.upload == "direct" ? OutOfCoreOptions::Upload::Direct
                                         : OutOfCoreOptions::Upload::Auto;
  o.reuseDeviceMemory = option.reuse == "on";
  o.emptySpaceSkipping = run.ess;
  o.storage = parseStorage(run.storage);
  return o;
}

double mibOf(size_t bytes) { return double(bytes) / double(1 << 20); }

// OutOfCoreStats::shown for the bench's reader.
const char* shownText(const std::string& shown) {
  return shown == "preview"  ? "a preview from the quick level"
         : shown == "coarse" ? "the coarse level"
                             : "full resolution";
}

}  // namespace

int renderOutOfCore(const OutOfCoreOption& option, SlabSource& source, const RenderParams& p,
                    const OutOfCoreRun& run, const std::string& output) {
  ClContext ctx(run.device);
  OutOfCoreRenderer r(ctx, source, optionsOf(option, run));
  Image img;
  OutOfCoreStats s;
  r.render(p, img, &s);
  writeImage(output, img);
  std::fprintf(
      stderr,
      "rendered %dx%d %s on %s out of core in %.0f ms (first frame includes the kernel "
      "builds): %d parts, %d held after it, %d uploaded (%.0f MiB%s; read %.0f ms, copied "
      "%.0f ms, kernels %.0f ms, %.0f ms of them overlapped); opening %.0f ms; %s%s%s\n",
      p.width, p.height, toString(p.mode), ctx.device().name.c_str(), s.totalMs, s.parts,
      s.partsResident, s.uploads, mibOf(s.bytesUploaded), s.pinned ? ", pinned" : "", s.readMs,
      s.uploadMs, s.kernelMs, s.overlapMs, r.openMs(),
      s.fullResolution ? "full resolution" : "NOT at full resolution",
      s.deviceOutOfMemory ? (": " + s.message).c_str() : "",
      s.redrawnForRange ? " (drawn twice: the value range grew as the parts were read)" : "");
  if (!s.note.empty()) std::cerr << "voxray-cli: warning: " << s.note << "\n";
  for (const std::string& w : source.geometry().warnings)
    std::cerr << "voxray-cli: warning: " << w << "\n";
  std::cerr << "-> " << output << "\n";
  return 0;
}

void benchOutOfCore(const OutOfCoreOption& option, SlabSource& source, const std::string& name,
                    const RenderParams& base, const OutOfCoreRun& run, const BenchRun& bench,
                    std::ostream& out) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto msSinceStart = [&] {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  ClContext ctx(run.device);
  const double contextMs = msSinceStart();
  RenderParams p = base;
  const OutOfCoreOptions options = optionsOf(option, run);
  // The first frame's programs built while the renderer reads the source's first level: a
  // failed build is built again, and reported, by the frame that needs it.
  std::jthread build([&] {
    try {
      OutOfCoreRenderer::prebuild(ctx, p, options);
    } catch (const Error&) {
    }
  });
  OutOfCoreRenderer r(ctx, source, options);
  const double openedMs = msSinceStart();
  Image img;
  OutOfCoreStats s;
  // The first image: the source's quick (or coarse) level, then a preview (its kernels built
  // by then or waited for).
  r.preview(p, img, &s);
  const double firstMs = msSinceStart();
  build.join();
  const double firstCells = s.cellsKnown;
  const std::string firstShown = s.shown;
  if (run.firstOnly) {
    if (run.json) {
      out << nlohmann::json{{"input", name},
                            {"size", std::to_string(p.width) + "x" + std::to_string(p.height)},
                            {"device", ctx.device().name},
                            {"source", source.describe()},
                            {"context_ms", contextMs},
                            {"open_ms", r.openMs()},
                            {"opened_at_ms", openedMs},
                            {"first_image_ms", firstMs},
                            {"first_image_shown", firstShown},
                            {"peak_rss_mib", residentMiB(true)}}
                 .dump()
          << "\n";
    } else {
      char line[512];
      std::snprintf(line, sizeof(line),
                    "%s %dx%d %s on %s: first image %.0f ms (%s; context %.0f ms, opening %.0f "
                    "ms, frame from %.0f ms); peak resident memory %.0f MiB\n",
                    name.c_str(), p.width, p.height, toString(p.mode), ctx.device().name.c_str(),
                    firstMs, shownText(firstShown), contextMs, r.openMs(), openedMs,
                    residentMiB(true));
      out << line;
    }
    return;
  }
  r.render(p, img, &s);  // the converged frame's kernels, and the cache filled
  const double convergedAtMs =
      std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  const bool redrawn = s.redrawnForRange;
  const std::string note = s.note;
  std::vector<double> preview, converged, uploaded, uploads, readMs, uploadMs, kernelMs, overlapMs,
      allocations;
  bool pinned = false;
  int coarseParts = 0;
  for (int i = 0; i < bench.frames; ++i) {
    orbitCamera(p.camera, bench.orbit, i, bench.frames);
    r.preview(p, img, &s);
    preview.push_back(s.totalMs);
    coarseParts = s.partsCoarse;
  }
  for (int i = 0; i < bench.frames; ++i) {
    orbitCamera(p.camera, bench.orbit, i, bench.frames);
    r.render(p, img, &s);
    converged.push_back(s.totalMs);
    uploaded.push_back(mibOf(s.bytesUploaded));
    uploads.push_back(double(s.uploads));
    readMs.push_back(s.readMs);
    uploadMs.push_back(s.uploadMs);
    kernelMs.push_back(s.kernelMs);
    overlapMs.push_back(s.overlapMs);
    allocations.push_back(double(s.allocations));
    pinned = pinned || s.pinned;
  }
  const double previewMs = median(preview), convergedMs = median(converged);
  const double peak = residentMiB(true);
  const double volumeMib = mibOf(source.geometry().byteSize());
  if (run.json) {
    out << nlohmann::json{{"input", name},
                          {"size", std::to_string(p.width) + "x" + std::to_string(p.height)},
                          {"mode", toString(p.mode)},
                          {"device", ctx.device().name},
                          {"source", source.describe()},
                          {"volume_mib", volumeMib},
                          {"budget_mib", option.budgetMib},
                          {"parts", r.partCount()},
                          {"parts_resident", r.residentCount()},
                          {"preview_coarse_parts", coarseParts},
                          {"open_ms", r.openMs()},
                          {"first_image_ms", firstMs},
                          {"first_image_cells_known", firstCells},
                          {"first_image_shown", firstShown},
                          {"context_ms", contextMs},
                          {"opened_at_ms", openedMs},
                          {"first_converged_at_ms", convergedAtMs},
                          {"first_converged_redrawn", redrawn},
                          {"note", note},
                          {"preview_median_ms", previewMs},
                          {"preview_fps", 1000.0 / previewMs},
                          {"converged_median_ms", convergedMs},
                          {"uploads_per_converged_frame", median(uploads)},
                          {"uploaded_mib_per_converged_frame", median(uploaded)},
                          {"upload_path", pinned ? "pinned" : "direct"},
                          {"converged_read_ms", median(readMs)},
                          {"converged_upload_ms", median(uploadMs)},
                          {"converged_kernel_ms", median(kernelMs)},
                          {"converged_overlap_ms", median(overlapMs)},
                          {"device_allocations_per_converged_frame", median(allocations)},
                          {"peak_rss_mib", peak}}
               .dump()
        << "\n";
    return;
  }
  char line[1024];
  std::snprintf(line, sizeof(line),
                "%s %dx%d %s on %s, %s: %.0f MiB volume, budget %zu MiB: %d parts, %d held\n"
                "  first image %.0f ms (%s; context %.0f ms, opening %.0f ms: the first level; "
                "frame from %.0f ms); first converged frame done at %.0f ms%s\n"
                "  preview (orbit, %d parts coarse): median %.1f ms, %.2f fps\n"
                "  converged: median %.0f ms, %.0f parts / %.0f MiB uploaded per frame (%s, %.0f "
                "device allocations)\n"
                "    per converged frame: read %.0f ms, upload %.0f ms, kernels %.0f ms, of "
                "which %.0f ms overlapped\n"
                "  peak resident memory %.0f MiB; %d frames each over a 360-degree orbit; "
                "medians\n",
                name.c_str(), p.width, p.height, toString(p.mode), ctx.device().name.c_str(),
                source.describe().c_str(), volumeMib, option.budgetMib, r.partCount(),
                r.residentCount(), firstMs, shownText(firstShown), contextMs, r.openMs(), openedMs,
                convergedAtMs, redrawn ? " (drawn twice: the range grew)" : "", coarseParts,
                previewMs, 1000.0 / previewMs, convergedMs, median(uploads), median(uploaded),
                pinned ? "pinned" : "direct", median(allocations), median(readMs), median(uploadMs),
                median(kernelMs), median(overlapMs), peak, bench.frames);
  out << line;
  if (!note.empty()) out << "  note: " << note << "\n";
}

}  // namespace voxray::cli
