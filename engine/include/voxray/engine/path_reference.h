#pragma once
// The path tracer's estimator (path_tracer.h) in double precision on the host, for small
// images and volumes: the ground truth the kernel is measured against. It reports its own
// standard error per pixel, so a comparison can say how far apart is too far.
#include "voxray/engine/path_tracer.h"

namespace voxray {

struct Volume;

struct PathReference {
  FloatImage mean;           // linear RGB per pixel, not clamped
  FloatImage standardError;  // of each pixel's mean: sample deviation / sqrt(samples)
  int samples = 0;
};

// `samples` paths per pixel with the kernel's random-number scheme (kernels/path_rng.h)
// under options.seed. Throws Error (Input) for samples < 2 or bad options.
PathReference renderPathReference(const Volume& v, const RenderParams& p, int samples,
                                  const PathTracerOptions& options = {});

}  // namespace voxray
