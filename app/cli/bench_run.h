#pragma once
// One bench case: frames over a 360-degree orbit after a warm-up, timed per frame, and
// the rows that voxray-cli bench prints (text, JSON or CSV).
#include <string>
#include <vector>

#include "voxray/engine/orbit.h"
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

struct BenchRow {
  std::string input, size, mode, gradient, kernel;
  int pixels = 0;
  double medianMs = 0, minMs = 0, maxMs = 0, fps = 0;
  double kernelMs = 0;     // median of the profiling events
  double raysPerS = 0;     // pixels / median wall time
  double samplesPerS = 0;  // counted samples of the orbit / their wall time; 0 = not counted
  double seedFps = 0;      // the seed paper's figure for this cell, 0 if none
  double coarseMs = 0;     // a quarter-size frame: what progressive rendering shows first
  // shadows, ao: the light grid's precomputation (the kernels already built; a median of 3)
  // and its median cost per timed frame (0 while only the camera moves: a fixed --light).
  std::string lighting = "phong";
  double lightBuildMs = 0, lightFrameMs = 0;
};

struct BenchRun {
  int frames = 12, warmup = 2;
  bool countSamples = true;  // one more orbit with the counting kernel, untimed for fps
  Orbit orbit = Orbit::Azimuth;
};

// Renders p over the orbit (0 ... 360 degrees) and measures it.
BenchRow benchCase(Raycaster& rc, RenderParams p, const BenchRun& run);

enum class BenchFormat { Text, Json, Csv };
void printHeader(BenchFormat f);
void printRow(BenchFormat f, const BenchRow& r);  // Text and Csv print as they go
void printFooter(BenchFormat f, const std::vector<BenchRow>& rows, const std::string& device,
                 int frames);
// Resident and peak memory of this process in MiB (Linux /proc; 0 elsewhere).
double residentMiB(bool peak);

}  // namespace voxray::cli
