// voxray-cli bench: frames over a 360-degree orbit after a warm-up, per size x gradient,
// reporting medians (these machines are noisy) and kernel time beside wall time.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "input_options.h"
#include "render_flags.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray::cli {

VolumeStorage parseStorage(const std::string& s);

namespace {

struct BenchOptions {
  InputOptions input;
  RenderFlags flags;
  std::string sizes = "512x384,640x480,800x600,1024x768", gradients = "central", device;
  std::string storage = "auto";
  int frames = 12, warmup = 2;
  bool json = false, csv = false;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

Run addBenchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("bench", "Frame times over an orbit (median, min, max)");
  auto o = std::make_shared<BenchOptions>();
  o->input.add(*cmd);
  cmd->add_option("--sizes", o->sizes, "comma-separated WxH list");
  cmd->add_option("--gradients", o->gradients, "comma-separated operators");
  cmd->add_option("--frames", o->frames, "timed frames per case (an orbit)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--warmup", o->warmup, "untimed frames first (kernel build)");
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number");
  cmd->add_option("--storage", o->storage, "auto, buffer or image")
      ->check(CLI::IsMember({"auto", "buffer", "image"}));
  cmd->add_flag("--json", o->json, "machine-readable output");
  cmd->add_flag("--csv", o->csv, "CSV output");
  o->flags.add(*cmd, {"size", "gradient", "azimuth"});
  return [o] {
    RenderParams base = o->flags.params();
    Volume v = o->input.load();
    ClContext ctx(o->device);
    Raycaster rc(ctx, v, parseStorage(o->storage));
    nlohmann::json rows = nlohmann::json::array();
    if (o->csv)
      std::cout << "input,size,mode,gradient,median_ms,min_ms,max_ms,fps,kernel_ms,mrays_s\n";
    else if (!o->json)
      std::printf("%-10s %-6s %-14s %9s %9s %9s %8s %9s %9s\n", "size", "mode", "gradient",
                  "median_ms", "min_ms", "max_ms", "fps", "kernel_ms", "Mrays/s");
    Image img;
    for (const auto& size : split(o->sizes))
      for (const auto& grad : split(o->gradients)) {
        RenderParams p = base;
        renderParamSpecs()[0].parse(p, size);  // "size"
        p.gradient = parseGradient(grad);
        std::vector<double> wall, kernel;
        for (int i = -o->warmup; i < o->frames; ++i) {
          p.camera.azimuthDeg = 360.0 * std::max(i, 0) / o->frames;
          FrameStats s;
          rc.render(p, img, &s);
          if (i < 0) continue;
          wall.push_back(s.totalMs);
          kernel.push_back(s.kernelMs);
        }
        double med = median(wall), fps = 1000.0 / med;
        double mrays = double(p.width) * p.height / (med * 1e3);
        auto [mn, mx] = std::minmax_element(wall.begin(), wall.end());
        std::string input = o->input.input.empty() ? "phantom" : o->input.input;
        if (o->json)
          rows.push_back({{"input", input},
                          {"size", size},
                          {"mode", toString(p.mode)},
                          {"gradient", grad},
                          {"median_ms", med},
                          {"min_ms", *mn},
                          {"max_ms", *mx},
                          {"fps", fps},
                          {"kernel_ms", median(kernel)},
                          {"mrays_per_s", mrays},
                          {"device", ctx.device().name}});
        else if (o->csv)
          std::cout << input << "," << size << "," << toString(p.mode) << "," << grad << "," << med
                    << "," << *mn << "," << *mx << "," << fps << "," << median(kernel) << ","
                    << mrays << "\n";
        else
          std::printf("%-10s %-6s %-14s %9.1f %9.1f %9.1f %8.2f %9.1f %9.2f\n", size.c_str(),
                      toString(p.mode), grad.c_str(), med, *mn, *mx, fps, median(kernel), mrays);
      }
    if (o->json)
      std::cout << rows.dump(2) << "\n";
    else if (!o->csv)
      std::printf("device: %s, %d frames per case over a 360-degree orbit\n",
                  ctx.device().name.c_str(), o->frames);
    return 0;
  };
}

}  // namespace voxray::cli
