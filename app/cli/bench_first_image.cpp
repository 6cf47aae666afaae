#include "bench_first_image.h"

#include <chrono>
#include <cstdio>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "bench_run.h"
#include "json_text.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/coarse_level.h"
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

VolumeStorage parseStorage(const std::string& s);

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

struct Step {
  std::string name;
  double ms = 0.0;
  double peakMiB = 0.0;  // the process's peak resident memory after the step
  std::string note;
};

}  // namespace

int benchFirstImage(const InputOptions& input, const RenderParams& params,
                    const FirstImageOptions& o, std::ostream& out) {
  const Clock::time_point start = Clock::now();
  std::vector<Step> steps;
  auto step = [&](const std::string& name, Clock::time_point t, std::string note = {}) {
    steps.push_back({name, msSince(t), residentMiB(true), std::move(note)});
  };
  Clock::time_point t = Clock::now();
  const Volume v = input.load();
  step("read", t,
       std::to_string(v.dims.x) + "x" + std::to_string(v.dims.y) + "x" + std::to_string(v.dims.z));
  t = Clock::now();
  ClContext ctx(o.device);
  step("context", t, ctx.device().name);
  double firstImageMs = 0.0, coarseFrameMs = 0.0;
  Image img;
  std::unique_ptr<Raycaster> coarseRc;
  Volume coarse;
  if (o.coarseFactor > 1) {
    t = Clock::now();
    coarse = coarseLevel(v, o.coarseFactor);
    step("coarse level", t,
         std::to_string(o.coarseFactor) + "x box mean, " + std::to_string(coarse.dims.x) + "x" +
             std::to_string(coarse.dims.y) + "x" + std::to_string(coarse.dims.z));
    t = Clock::now();
    coarseRc = std::make_unique<Raycaster>(ctx, coarse, parseStorage(o.storage));
    coarseRc->render(params, img);
    coarseFrameMs = msSince(t);
    step("coarse frame", t, "upload, tables, kernel build and frame: the coarse preview");
    firstImageMs = msSince(start);
    // Shown: the level and its tables go before the full volume's are made (the workstation
    // keeps its preview until the full upload is done; the peak differs by 1/64 of the volume).
    coarseRc.reset();
    coarse = Volume();
  }
  t = Clock::now();
  Raycaster rc(ctx, v, parseStorage(o.storage));
  const Raycaster::UploadTimes up = rc.uploadTimes();
  steps.push_back({"device upload", up.volumeMs, residentMiB(true),
                   std::to_string(rc.slabCount()) + " slab(s), " +
                       (rc.storage() == VolumeStorage::Image3d ? "image3d" : "buffer")});
  steps.push_back({"empty space", up.emptySpaceMs, residentMiB(true), "macro-cell tables"});
  t = Clock::now();
  FrameStats stats;
  rc.render(params, img, &stats);
  step("full frame", t,
       "kernel " + std::to_string(int(stats.kernelMs + 0.5)) +
           " ms; the value range and the table's classification included" +
           (o.coarseFactor > 1 ? "" : ", and the kernel build"));
  const double fullImageMs = msSince(start);
  if (o.coarseFactor <= 1) firstImageMs = fullImageMs;
  const double volumeMiB = double(v.byteSize()) / double(1 << 20);
  const double peakMiB = residentMiB(true);
  if (o.json) {
    nlohmann::json j;
    j["device"] = ctx.device().name;
    j["dims"] = {v.dims.x, v.dims.y, v.dims.z};
    j["volume_mib"] = volumeMiB;
    j["coarse_factor"] = o.coarseFactor;
    j["first_image_ms"] = firstImageMs;
    j["full_image_ms"] = fullImageMs;
    j["coarse_frame_ms"] = coarseFrameMs;
    j["peak_rss_mib"] = peakMiB;
    j["peak_rss_over_volume"] = peakMiB / volumeMiB;
    for (const Step& s : steps)
      j["steps"].push_back({{"step", s.name}, {"ms", s.ms}, {"peak_rss_mib", s.peakMiB}});
    out << jsonText(j) << "\n";
    return 0;
  }
  char line[256];
  std::snprintf(line, sizeof line, "first image: %dx%d %s on %s, volume %.0f MiB\n", params.width,
                params.height, toString(params.mode), ctx.device().name.c_str(), volumeMiB);
  out << line;
  for (const Step& s : steps) {
    std::snprintf(line, sizeof line, "  %-14s %9.1f ms  peak %7.0f MiB  %s\n", s.name.c_str(), s.ms,
                  s.peakMiB, s.note.c_str());
    out << line;
  }
  std::snprintf(line, sizeof line,
                "first image %.1f ms (%s), full image %.1f ms, peak RSS %.0f MiB = %.3f x the "
                "volume\n",
                firstImageMs, o.coarseFactor > 1 ? "coarse preview" : "full resolution",
                fullImageMs, peakMiB, peakMiB / volumeMiB);
  out << line;
  return 0;
}

}  // namespace voxray::cli
