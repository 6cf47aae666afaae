#pragma once
// voxray-cli's side of lighting cinematic (the progressive path tracer): its flags, the
// render loop (--spp / --seconds), bench's case and the convergence measurement that
// accuracy prints (PSNR and SSIM against the same frame converged, as a function of time).
#include <iosfwd>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_run.h"
#include "voxray/engine/path_tracer.h"
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

struct CinematicFlags {
  int spp = 0;           // paths per pixel; 0 with no --seconds: kDefaultSpp
  double seconds = 0.0;  // time to accumulate for; 0: until spp
  PathTracerOptions tracer;
  static constexpr int kDefaultSpp = 64;
  void add(CLI::App& cmd);
  // The still image's samples or seconds (kDefaultSpp when neither is given).
  StillBudget budget() const;
};

// After a progressive still (STATS.pathSamples > 0): how many samples it took, on LOG.
void logPathRun(const FrameStats& stats, const CinematicFlags& f, std::ostream& log);

// bench of a progressive renderer: one sample per pixel per frame after the warm-up, the
// camera still (the accumulation never restarts); rays/s is paths per second.
BenchRow benchPasses(Renderer& renderer, const RenderParams& p, const BenchRun& run);

struct ConvergenceFlags {
  int convergedSpp = 4096;
  std::string checkpoints = "1,2,5,10,20,30,60";  // seconds
  void add(CLI::App& cmd);
};

struct ConvergencePoint {
  double seconds = 0.0;  // accumulating time when measured (kernel launches and reads)
  // This process's CPU time (all threads) over the same launches: on a CPU device, what
  // they cost when other load shares the cores (seconds on N idle cores: cpuSeconds / N).
  double cpuSeconds = 0.0;
  int samples = 0;
  double psnrDb = 0.0, ssim = 0.0;
};

// The frame converged at convergedSpp under seed + 1, then accumulated afresh under the
// flags' seed, measured at each checkpoint: both images clamped to 0 ... 1 as displayed.
std::vector<ConvergencePoint> cinematicConvergence(Raycaster& rc, const RenderParams& p,
                                                   const CinematicFlags& f,
                                                   const ConvergenceFlags& c, std::ostream& log);
void printConvergence(const std::vector<ConvergencePoint>& points, const RenderParams& p,
                      const std::string& device, int convergedSpp, bool json);

}  // namespace voxray::cli
