// voxray-cli accuracy: the speed/accuracy sweep (docs/accuracy/README.md). Analytic
// scenes are made in code; INPUT (optional) adds a real-data scene scored against the
// reference renderer at 1/16-voxel steps.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cinematic_run.h"
#include "commands.h"
#include "input_options.h"
#include "json_text.h"
#include "render_flags.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"
#include "voxray/lab/accuracy_plot.h"
#include "voxray/lab/accuracy_sweep.h"

namespace voxray::cli {

namespace {

struct AccuracyOptions {
  InputOptions input;
  RenderFlags flags;
  std::string scenes = "ml41-iso,ml41-dvr,ml41-mip,ml81-iso/r,sphere64-iso/r,torus64-iso/r";
  std::string syntheticSize = "128x128", device, plot;
  int frames = 3;
  bool json = false, quiet = false;
  CinematicFlags cinematic;
  ConvergenceFlags convergence;
};

// "ml41-iso/r": shape, voxels per axis, mode, and /r for the reduced set of cases.
struct SceneToken {
  SyntheticSpec spec;
  Mode mode = Mode::Iso;
  bool reduced = false;
};

SceneToken parseScene(const std::string& token) {
  SceneToken t;
  std::string s = token;
  if (s.size() > 2 && s.substr(s.size() - 2) == "/r") {
    t.reduced = true;
    s.resize(s.size() - 2);
  }
  size_t dash = s.find('-');
  size_t digit = s.find_first_of("0123456789");
  if (dash == std::string::npos || digit == std::string::npos || digit > dash)
    throw inputError("--scenes: '" + token + "' is not SHAPE<voxels>-MODE[/r], e.g. ml41-iso");
  t.spec.shape = parseSyntheticShape(s.substr(0, digit));
  t.spec.size = std::stoi(s.substr(digit, dash - digit));
  t.mode = parseMode(s.substr(dash + 1));
  return t;
}

RenderParams syntheticBase(Mode mode, const std::string& size, Lighting lighting) {
  RenderParams p;
  p.lighting = lighting;  // --lighting holds for the analytic scenes as for INPUT
  findRenderParamSpec("size").parse(p, size);
  p.mode = mode;
  p.isoLo = 0.0;  // analytic fields have their surface at value 0
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 25.0;
  p.camera.zoom = 1.2;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";  // -1000..1000 "HU" of Marschner-Lobb
  return p;
}

std::string num(double v, int prec) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", prec, v);
  return b;
}

void printTable(const std::vector<SweepRow>& rows, const std::string& device) {
  std::printf("%-12s %-32s %8s %8s %8s %6s %8s %8s %8s %7s %7s %8s %6s %6s\n", "scene", "setting",
              "ms", "Msamp/s", "hit_med", "miss%", "surf_vox", "surf_p95", "k_surf", "nrm_deg",
              "nrm_p95", "rmse", "psnr", "ssim");
  for (const SweepRow& r : rows) {
    bool iso = r.mode == Mode::Iso && r.hitPoint.count > 0;
    double miss = 100.0 * r.hitPoint.excluded / std::max(1, r.hitPoint.count + r.hitPoint.excluded);
    std::printf("%-12s %-32s %8.1f %8.2f %8s %6s %8s %8s %8s %7s %7s %8.5f %6.2f %6.4f\n",
                r.scene.c_str(), r.setting.c_str(), r.msPerFrame, r.samplesPerSecond * 1e-6,
                iso ? num(r.hitPoint.median, 5).c_str() : "-", iso ? num(miss, 2).c_str() : "-",
                r.hasSurface ? num(r.surface.positionVoxels.mean, 4).c_str() : "-",
                r.hasSurface ? num(r.surface.positionVoxels.p95, 4).c_str() : "-",
                r.hasSurface ? num(r.kernelSurface.mean, 4).c_str() : "-",
                r.hasSurface ? num(r.surface.normalDeg.mean, 2).c_str() : "-",
                r.hasSurface ? num(r.surface.normalDeg.p95, 2).c_str() : "-", r.image.rmse,
                r.image.psnrDb, r.image.ssim);
  }
  std::printf(
      "device: %s. ms: median wall time per OpenCL frame; Msamp/s: volume reads counted by the "
      "reference renderer / ms; hit_med: median distance of the hit point to the same "
      "reconstruction's crossing marched at 1/16 voxel with 24 bisections; miss%%: rays that "
      "found another crossing (stepped over a thin feature), left out of hit_med; surf/nrm: vs the "
      "analytic surface and normal (reference renderer's hits); k_surf: the OpenCL kernel's own "
      "hit points vs the analytic surface (mean); rmse/psnr/ssim: "
      "OpenCL image vs the reference renderer at 1/16 voxel steps (trilinear); rows of lighting "
      "shadows or ao (_shadows, _ao): vs the Monte Carlo reference, the mean of 4 samples at "
      "those steps with shadow and occlusion rays at half a voxel\n",
      device.c_str());
}

nlohmann::json toJson(const std::vector<SweepRow>& rows, const std::string& device) {
  nlohmann::json out = nlohmann::json::array();
  for (const SweepRow& r : rows) {
    nlohmann::json j = {{"scene", r.scene},
                        {"setting", r.setting},
                        {"mode", toString(r.mode)},
                        {"ms_per_frame", r.msPerFrame},
                        {"samples_per_s", r.samplesPerSecond},
                        {"rmse", r.image.rmse},
                        {"psnr_db", r.image.psnrDb},
                        {"ssim", r.image.ssim},
                        {"mae", r.image.meanAbs},
                        {"device", device}};
    if (r.hitPoint.count > 0)
      j["hit_point_voxels"] = {{"mean", r.hitPoint.mean},
                               {"median", r.hitPoint.median},
                               {"p95", r.hitPoint.p95},
                               {"other_crossing", r.hitPoint.excluded}};
    if (r.hasSurface) {
      j["surface_voxels"] = {{"mean", r.surface.positionVoxels.mean},
                             {"p95", r.surface.positionVoxels.p95},
                             {"max", r.surface.positionVoxels.max}};
      j["normal_deg"] = {{"mean", r.surface.normalDeg.mean}, {"p95", r.surface.normalDeg.p95}};
      j["kernel_surface_voxels"] = {{"mean", r.kernelSurface.mean},
                                    {"p95", r.kernelSurface.p95},
                                    {"max", r.kernelSurface.max}};
    }
    out.push_back(j);
  }
  return out;
}

}  // namespace

Run addAccuracyCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "accuracy", "Speed/accuracy sweep: step, interpolation, gradient, refinement, resolution");
  auto o = std::make_shared<AccuracyOptions>();
  o->input.add(*cmd);
  cmd->add_option("--scenes", o->scenes,
                  "comma-separated SHAPE<voxels>-MODE[/r] (shapes ml, sphere, torus, ramp; /r: "
                  "reduced cases); 'none' for INPUT only");
  cmd->add_option("--synthetic-size", o->syntheticSize, "image size of the analytic scenes");
  cmd->add_option("--frames", o->frames, "timed OpenCL frames per case (median)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--device", o->device, "auto, cpu, gpu or a device number");
  cmd->add_option("--plot", o->plot, "write an error-vs-time (Pareto) plot to this PNG");
  cmd->add_flag("--json", o->json, "machine-readable output");
  cmd->add_flag("--quiet", o->quiet, "no progress lines on stderr");
  o->flags.add(*cmd, {"step", "interp", "gradient", "refine", "jitter"});
  o->cinematic.add(*cmd);
  o->convergence.add(*cmd);
  return [o] {
    ClContext ctx(o->device);
    if (o->flags.params().lighting == Lighting::Cinematic) {
      // The path tracer against its own converged image (INPUT, or the phantom), by time.
      Volume v = o->input.load();
      Raycaster rc(ctx, v);
      RenderParams p = o->flags.params();
      auto points = cinematicConvergence(rc, p, o->cinematic, o->convergence, std::cerr);
      printConvergence(points, p, ctx.device().name, o->convergence.convergedSpp, o->json);
      return 0;
    }
    SweepOptions so;
    so.frames = o->frames;
    if (!o->quiet) so.progress = [](const std::string& s) { std::cerr << "  " << s << "\n"; };
    std::vector<SweepRow> rows;
    auto run = [&](const SweepScene& scene, bool reduced) {
      auto r = runSweep(ctx, scene, standardCases(scene, reduced), so);
      rows.insert(rows.end(), r.begin(), r.end());
    };
    if (o->scenes != "none") {
      std::stringstream ss(o->scenes);
      std::string token;
      while (std::getline(ss, token, ',')) {
        SceneToken t = parseScene(token);
        Volume v = makeSyntheticVolume(t.spec);
        SweepScene scene{token.substr(0, token.find('/')), &v, AnalyticField{t.spec},
                         syntheticBase(t.mode, o->syntheticSize, o->flags.params().lighting)};
        run(scene, t.reduced);
      }
    }
    if (!o->input.input.empty()) {
      Volume v = o->input.load();
      RenderParams base = o->flags.params();
      if (o->flags.given.count("size") == 0) base.width = 160, base.height = 120;
      run(SweepScene{"input-" + std::string(toString(base.mode)), &v, std::nullopt, base}, false);
    }
    const std::string device = ctx.device().name;
    if (o->json)
      std::cout << jsonText(toJson(rows, device)) << "\n";
    else
      printTable(rows, device);
    if (!o->plot.empty()) {
      writeImage(o->plot, accuracyPlot(rows));
      std::cerr << "plot -> " << o->plot << "\n";
    }
    return 0;
  };
}

}  // namespace voxray::cli
