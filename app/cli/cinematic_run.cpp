#include "cinematic_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "json_text.h"
#include "voxray/io/error.h"
#include "voxray/io/statistics.h"
#include "voxray/lab/accuracy.h"

namespace voxray::cli {

namespace {

FloatImage displayed(FloatImage f) {
  for (float& x : f.rgb) x = std::clamp(x, 0.0f, 1.0f);
  return f;
}

std::vector<double> parseSeconds(const std::string& list) {
  std::vector<double> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    double s = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !(s > 0.0))
      throw inputError("--checkpoints: '" + item + "' is not a positive number of seconds");
    out.push_back(s);
  }
  if (out.empty()) throw inputError("--checkpoints: give at least one time in seconds");
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

void CinematicFlags::add(CLI::App& cmd) {
  cmd.add_option("--spp", spp,
                 "lighting cinematic: paths per pixel (default " + std::to_string(kDefaultSpp) +
                     " when --seconds is not given)")
      ->check(CLI::Range(1, 1 << 24));
  cmd.add_option("--seconds", seconds, "lighting cinematic: accumulate for this long")
      ->check(CLI::Range(0.001, 1e6));
  cmd.add_option("--seed", tracer.seed,
                 "lighting cinematic: random seed (same seed and "
                 "--spp: the same image on a given device)");
  cmd.add_option("--bounces", tracer.maxBounces,
                 "lighting cinematic: scatters per path (1: single scattering)")
      ->check(CLI::Range(1, 64));
}

StillBudget CinematicFlags::budget() const {
  return StillBudget{spp == 0 && seconds <= 0.0 ? kDefaultSpp : spp, seconds};
}

void logPathRun(const FrameStats& stats, const CinematicFlags& f, std::ostream& log) {
  if (stats.pathSamples == 0) return;
  log << "path-traced " << stats.pathSamples << " samples per pixel in " << stats.pathSeconds
      << " s (" << f.tracer.maxBounces << " bounces, seed " << f.tracer.seed << ")\n";
}

BenchRow benchPasses(Renderer& renderer, const RenderParams& p, const BenchRun& run) {
  Image img;
  std::vector<double> ms;
  for (int i = -run.warmup; i < run.frames; ++i) {
    auto t = std::chrono::steady_clock::now();
    renderer.render(p, img);
    if (i >= 0)
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count());
  }
  BenchRow r;
  r.size = std::to_string(p.width) + "x" + std::to_string(p.height);
  r.mode = toString(p.mode);
  r.gradient = "-";
  r.kernel = "path";
  r.pixels = p.width * p.height;
  r.medianMs = median(ms);
  r.minMs = ms.empty() ? 0.0 : *std::min_element(ms.begin(), ms.end());
  r.maxMs = ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end());
  r.fps = 1000.0 / r.medianMs;  // samples per pixel per second
  r.kernelMs = r.medianMs;
  r.raysPerS = r.pixels / (r.medianMs * 1e-3);
  return r;
}

void ConvergenceFlags::add(CLI::App& cmd) {
  cmd.add_option("--converged-spp", convergedSpp,
                 "lighting cinematic: paths per pixel of the converged image")
      ->check(CLI::Range(2, 1 << 24));
  cmd.add_option("--checkpoints", checkpoints,
                 "lighting cinematic: comma-separated seconds at which to measure");
}

std::vector<ConvergencePoint> cinematicConvergence(Raycaster& rc, const RenderParams& p,
                                                   const CinematicFlags& f,
                                                   const ConvergenceFlags& c, std::ostream& log) {
  std::vector<double> checkpoints = parseSeconds(c.checkpoints);
  PathTracer pt(rc);
  PathTracerOptions o = f.tracer;
  o.seed = f.tracer.seed + 1;  // independent of the run measured
  pt.setOptions(o);
  Image img;
  PathProgress conv = pt.run(p, c.convergedSpp, 0.0, img, 2.0);
  FloatImage reference = displayed(pt.radiance());
  log << "converged image: " << conv.samples << " samples per pixel in " << conv.seconds << " s\n";
  pt.setOptions(f.tracer);
  std::vector<ConvergencePoint> out;
  int batch = 1;
  double cpu = 0.0;
  for (double checkpoint : checkpoints) {
    // Launches sized from the last so that the checkpoint is not overshot by much.
    while (pt.progress().seconds < checkpoint) {
      PathProgress before = pt.progress();
      std::clock_t c0 = std::clock();
      PathProgress now = pt.accumulate(p, batch, img);
      cpu += double(std::clock() - c0) / CLOCKS_PER_SEC;
      double perSample = (now.seconds - before.seconds) / batch;
      double left = checkpoint - now.seconds;
      batch = int(std::clamp(left / std::max(perSample, 1e-9), 1.0, 65536.0));
    }
    ImageError e = compareImages(displayed(pt.radiance()), reference);
    out.push_back({pt.progress().seconds, cpu, pt.progress().samples, e.psnrDb, e.ssim});
    log << "  " << out.back().seconds << " s: " << out.back().samples << " spp, PSNR " << e.psnrDb
        << " dB\n";
  }
  return out;
}

void printConvergence(const std::vector<ConvergencePoint>& points, const RenderParams& p,
                      const std::string& device, int convergedSpp, bool json) {
  if (json) {  // one object: the setting, then a row per checkpoint (columns)
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& c : points)
      rows.push_back({c.seconds, c.cpuSeconds, c.samples, c.psnrDb, c.ssim});
    std::cout << jsonText({{"device", device},
                           {"size", std::to_string(p.width) + "x" + std::to_string(p.height)},
                           {"converged_spp", convergedSpp},
                           {"columns", {"seconds", "cpu_s", "spp", "psnr_db", "ssim"}},
                           {"points", rows}})
              << "\n";
    return;
  }
  std::printf("%10s %10s %8s %8s %7s\n", "seconds", "cpu_s", "spp", "psnr_db", "ssim");
  for (const auto& c : points)
    std::printf("%10.2f %10.2f %8d %8.2f %7.4f\n", c.seconds, c.cpuSeconds, c.samples, c.psnrDb,
                c.ssim);
  std::printf(
      "device: %s. %dx%d, lighting cinematic: the image after accumulating that long (kernel "
      "launches and read-back) against the same frame at %d spp under another seed, both "
      "clamped to 0 ... 1 as displayed; PSNR peak 1, SSIM of luma; cpu_s: this process's CPU "
      "time over those launches\n",
      device.c_str(), p.width, p.height, convergedSpp);
}

}  // namespace voxray::cli
