#include "bench_run.h"
#include "json_text.h"
#include "voxray/io/statistics.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace voxray::cli {

BenchRow benchCase(Raycaster& rc, RenderParams p, const BenchRun& run) {
  RaycasterOptions opts = rc.options();
  opts.countSamples = false;
  rc.setOptions(opts);
  Image img;
  std::vector<double> wall, kernel, light;
  std::string variant;
  for (int i = -run.warmup; i < run.frames; ++i) {
    orbitCamera(p.camera, run.orbit, std::max(i, 0), run.frames);
    FrameStats s;
    rc.render(p, img, &s);
    if (i < 0) continue;
    wall.push_back(s.totalMs);
    variant = s.variant;
    kernel.push_back(s.kernelMs);
    light.push_back(s.lightingMs);
  }
  BenchRow r;
  r.size = std::to_string(p.width) + "x" + std::to_string(p.height);
  r.mode = toString(p.mode);
  r.gradient = toString(p.gradient);
  r.kernel = opts.kernel == RaycasterOptions::Kernel::Uber   ? "uber"
             : variant.find("PACKET=1") != std::string::npos ? "packet"
                                                             : "specialised";
  r.pixels = p.width * p.height;
  r.medianMs = median(wall);
  r.minMs = *std::min_element(wall.begin(), wall.end());
  r.maxMs = *std::max_element(wall.begin(), wall.end());
  r.fps = 1000.0 / r.medianMs;
  r.kernelMs = median(kernel);
  r.raysPerS = r.pixels / (r.medianMs * 1e-3);
  r.lighting = toString(p.lighting);
  r.lightFrameMs = median(light);
  if (p.lighting != Lighting::Phong) {
    // The grid alone: the clip box nudged (invisibly) forces a rebuild per frame.
    std::vector<double> builds;
    RenderParams q = p;
    for (int i = 0; i < 3; ++i) {
      q.clip.hi.x = 1.0 - 1e-6 * (i + 1);
      FrameStats s;
      rc.render(q, img, &s);
      builds.push_back(s.lightingMs);
    }
    r.lightBuildMs = median(builds);
  }
  // Time to the first coarse frame: a quarter of the size each way (1/16 of the rays),
  // as an interactive view shows while the camera moves before refining at rest.
  RenderParams coarse = p;
  coarse.width = std::max(1, p.width / 4);
  coarse.height = std::max(1, p.height / 4);
  std::vector<double> coarseMs;
  for (int i = -1; i < 5; ++i) {
    FrameStats s;
    rc.render(coarse, img, &s);
    if (i >= 0) coarseMs.push_back(s.totalMs);
  }
  r.coarseMs = median(coarseMs);
  if (run.countSamples) {
    // The counting kernel adds an atomic per ray, so it is not the one timed above: its
    // counts over the same orbit divide by the timed frames' total wall time.
    opts.countSamples = true;
    rc.setOptions(opts);
    double samples = 0, ms = 0;
    for (int i = -1; i < run.frames; ++i) {  // the first builds the kernel
      orbitCamera(p.camera, run.orbit, std::max(i, 0), run.frames);
      FrameStats s;
      rc.render(p, img, &s);
      if (i >= 0) samples += s.samples;
    }
    for (double w : wall) ms += w;
    r.samplesPerS = samples / (ms * 1e-3);
    opts.countSamples = false;
    rc.setOptions(opts);
  }
  return r;
}

void printHeader(BenchFormat f) {
  if (f == BenchFormat::Csv)
    std::cout << "input,size,mode,gradient,kernel,median_ms,min_ms,max_ms,fps,kernel_ms,"
                 "mrays_s,gsamples_s,coarse_ms,seed_fps,ratio,lighting,light_build_ms,"
                 "light_frame_ms\n";
  else if (f == BenchFormat::Text)
    std::printf("%-10s %-10s %-4s %-13s %-5s %9s %8s %8s %8s %9s %8s %8s %9s %8s %6s\n", "input",
                "size", "mode", "gradient", "kern", "median_ms", "min_ms", "max_ms", "fps",
                "kernel_ms", "Mrays/s", "Gsmp/s", "coarse_ms", "seed_fps", "ratio");
}

void printRow(BenchFormat f, const BenchRow& r) {
  double ratio = r.seedFps > 0 ? r.fps / r.seedFps : 0.0;
  std::string kern = r.kernel == "specialised" ? "spec"
                     : r.kernel == "packet"    ? "pack"
                     : r.kernel == "path"      ? "path"
                                               : "uber";
  if (f == BenchFormat::Csv)
    std::cout << r.input << "," << r.size << "," << r.mode << "," << r.gradient << "," << r.kernel
              << "," << r.medianMs << "," << r.minMs << "," << r.maxMs << "," << r.fps << ","
              << r.kernelMs << "," << r.raysPerS * 1e-6 << "," << r.samplesPerS * 1e-9 << ","
              << r.coarseMs << "," << r.seedFps << "," << ratio << "," << r.lighting << ","
              << r.lightBuildMs << "," << r.lightFrameMs << std::endl;
  else if (f == BenchFormat::Text) {
    std::printf("%-10s %-10s %-4s %-13s %-5s %9.1f %8.1f %8.1f %8.2f %9.1f %8.2f %8.3f %9.1f",
                r.input.c_str(), r.size.c_str(), r.mode.c_str(), r.gradient.c_str(), kern.c_str(),
                r.medianMs, r.minMs, r.maxMs, r.fps, r.kernelMs, r.raysPerS * 1e-6,
                r.samplesPerS * 1e-9, r.coarseMs);
    if (r.seedFps > 0)
      std::printf(" %8.2f %6.2f\n", r.seedFps, ratio);
    else
      std::printf(" %8s %6s\n", "-", "-");
    if (r.lighting != "phong")
      std::printf("%-10s lighting %s: light grid %.1f ms to build, %.1f ms per frame (median)\n",
                  "", r.lighting.c_str(), r.lightBuildMs, r.lightFrameMs);
    std::fflush(stdout);
  }
}

void printFooter(BenchFormat f, const std::vector<BenchRow>& rows, const std::string& device,
                 int frames) {
  if (f == BenchFormat::Json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& r : rows)
      out.push_back({{"input", r.input},
                     {"size", r.size},
                     {"mode", r.mode},
                     {"gradient", r.gradient},
                     {"kernel", r.kernel},
                     {"median_ms", r.medianMs},
                     {"min_ms", r.minMs},
                     {"max_ms", r.maxMs},
                     {"fps", r.fps},
                     {"kernel_ms", r.kernelMs},
                     {"rays_per_s", r.raysPerS},
                     {"samples_per_s", r.samplesPerS},
                     {"seed_fps", r.seedFps},
                     {"lighting", r.lighting},
                     {"light_build_ms", r.lightBuildMs},
                     {"light_frame_ms", r.lightFrameMs},
                     {"device", device}});
    std::cout << jsonText(out) << "\n";
  } else if (f == BenchFormat::Text) {
    std::printf("device: %s, %d frames per case over a 360-degree orbit after a warm-up\n",
                device.c_str(), frames);
    std::printf("memory: %.0f MiB resident now, %.0f MiB peak (the peak includes loading)\n",
                residentMiB(false), residentMiB(true));
  }
}

double residentMiB(bool peak) {
  std::ifstream f("/proc/self/status");
  std::string line, key = peak ? "VmHWM:" : "VmRSS:";
  while (std::getline(f, line))
    if (line.rfind(key, 0) == 0) {
      std::istringstream in(line.substr(key.size()));
      double kib = 0;
      in >> kib;
      return kib / 1024.0;
    }
  return 0.0;
}

}  // namespace voxray::cli
