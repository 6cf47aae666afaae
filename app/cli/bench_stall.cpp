#include "bench_stall.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <thread>

#include "refine_bands.h"
#include "voxray/io/statistics.h"

namespace voxray::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// This process's CPU time (all threads: PoCL's too), steadier than wall time on a loaded
// machine; on 2 idle cores a banded kernel's wall time is about half of it.
double cpuMs() { return 1e3 * double(std::clock()) / CLOCKS_PER_SEC; }

// The sharp frame as the worker renders it: about COUNT bands (1: the whole frame).
std::vector<RowBand> sharpBands(const RenderParams& sharp, int count) {
  if (count <= 1) return {{0, sharp.height}};
  const long pixels = long(sharp.width) * sharp.height;
  return refineBands(sharp.width, sharp.height, count, (pixels + count - 1) / count);
}

}  // namespace

StallFigures replayStall(Raycaster& rc, const RenderParams& drag, const RenderParams& sharp,
                         const StallCase& c, Orbit orbit, int dragFrames, int resumeMs) {
  Image dragImage, sharpImage;
  RenderParams d = drag, s = sharp;
  auto dragTo = [&](int i) {
    orbitCamera(d.camera, orbit, i, 180);
    rc.rendererFor(d).render(d, dragImage);
  };
  StallFigures f;
  // Rest: the drag, then nothing moves until the sharp frame is whole.
  const Clock::time_point t0 = Clock::now();
  Clock::time_point lastMove = t0;
  for (int i = 0; i < dragFrames; ++i) {
    lastMove = Clock::now();
    dragTo(i);
  }
  double shown = msSince(t0), shownCpu = cpuMs();  // the last drag frame
  const double lastDrag = shown;
  orbitCamera(s.camera, orbit, dragFrames - 1, 180);
  std::this_thread::sleep_until(lastMove + std::chrono::milliseconds(c.settleMs));
  const double sharpCpu0 = cpuMs();
  for (const RowBand& b : sharpBands(s, c.bands)) {
    rc.rendererFor(s).renderRows(s, sharpImage, b.y0, b.y1);
    const double now = msSince(t0);
    const double nowCpu = cpuMs();
    f.restGapMs = std::max(f.restGapMs, now - shown);
    f.restGapCpuMs = std::max(f.restGapCpuMs, nowCpu - shownCpu);
    shown = now;
    shownCpu = nowCpu;
  }
  f.sharpDoneMs = shown - lastDrag;
  f.sharpCpuMs = shownCpu - sharpCpu0;
  // Resume: the drag stops, the sharp frame is asked for, and RESUMEMS later the mouse
  // moves: its frame waits for the band (or whole frame) in flight, then comes first.
  for (int i = 0; i < dragFrames; ++i) {
    lastMove = Clock::now();
    dragTo(i);
  }
  const Clock::time_point asked = lastMove + std::chrono::milliseconds(c.settleMs);
  std::this_thread::sleep_until(asked);
  const Clock::time_point moved = asked + std::chrono::milliseconds(resumeMs);
  const double askedCpu = cpuMs();
  const RowBand first = sharpBands(s, c.bands).front();
  rc.rendererFor(s).renderRows(s, sharpImage, first.y0, first.y1);
  std::this_thread::sleep_until(moved);  // (no wait when the band took longer)
  dragTo(dragFrames);
  f.resumeWaitMs = msSince(moved);
  f.resumeCpuMs = cpuMs() - askedCpu;
  return f;
}

void printStallReplay(Raycaster& rc, const RenderParams& drag, const RenderParams& sharp,
                      Orbit orbit, int repeats) {
  const size_t bands = refineBands(sharp.width, sharp.height).size();
  const std::vector<StallCase> cases = {
      {"before: whole frame, settle 150 ms", 150, 1},
      {"after: " + std::to_string(bands) + " bands, settle 60 ms", 60, int(bands)},
      {"after: " + std::to_string(2 * bands) + " bands, settle 60 ms", 60, int(2 * bands)}};
  const int dragFrames = 8, resumeMs = 5;
  std::vector<std::vector<StallFigures>> runs(cases.size());
  replayStall(rc, drag, sharp, cases[2], orbit, 2, resumeMs);  // kernels built, caches warm
  for (int r = 0; r < repeats; ++r)
    for (size_t k = 0; k < cases.size(); ++k)
      runs[k].push_back(replayStall(rc, drag, sharp, cases[k], orbit, dragFrames, resumeMs));
  std::printf(
      "stall replay: drag frames %dx%d, sharp frame %dx%d (%zu bands), %d drag frames then "
      "rest; resume %d ms after the sharp frame is asked for; medians of %d\n",
      drag.width, drag.height, sharp.width, sharp.height, bands, dragFrames, resumeMs, repeats);
  for (size_t k = 0; k < cases.size(); ++k) {
    std::vector<double> gap, gapCpu, done, resume, resumeCpu, sharpCpu;
    for (const StallFigures& f : runs[k]) {
      gap.push_back(f.restGapMs);
      gapCpu.push_back(f.restGapCpuMs);
      done.push_back(f.sharpDoneMs);
      resume.push_back(f.resumeWaitMs);
      resumeCpu.push_back(f.resumeCpuMs);
      sharpCpu.push_back(f.sharpCpuMs);
    }
    std::printf(
        "  %-36s largest gap %7.1f ms wall %7.1f ms cpu; sharp frame %7.1f ms cpu, whole after "
        "%7.1f ms wall; resume wait %7.1f ms wall %7.1f ms cpu\n",
        cases[k].name.c_str(), median(gap), median(gapCpu), median(sharpCpu), median(done),
        median(resume), median(resumeCpu));
  }
  std::fflush(stdout);
}

}  // namespace voxray::cli
