#pragma once
// Error measures of the accuracy sweep: images against a reference image, and iso hit
// points and normals against analytic ground truth or a finely marched reference.
#include <vector>

#include "voxray/engine/reference_renderer.h"
#include "voxray/io/image.h"
#include "voxray/io/synthetic.h"

namespace voxray {

// Colour channels in 0..1. PSNR has peak 1 and is capped at 99 dB (identical images).
struct ImageError {
  double rmse = 0.0;
  double psnrDb = 99.0;
  double ssim = 1.0;     // mean SSIM of luma, Gaussian window sigma 1.5 (Wang et al. 2004)
  double meanAbs = 0.0;  // mean absolute difference per channel
};

FloatImage toFloatImage(const Image& image);
// Throws Error (Internal) when the sizes differ.
ImageError compareImages(const FloatImage& test, const FloatImage& reference);

struct ErrorStats {
  int count = 0;
  double mean = 0.0, median = 0.0, p95 = 0.0, max = 0.0;
  int excluded = 0;  // values left out (hitPointError: a different crossing was found)
};
ErrorStats summarize(std::vector<double> values);

struct SurfaceError {
  ErrorStats positionVoxels;  // distance of each hit point to the true surface
  ErrorStats normalDeg;       // angle between the computed and the true normal
};
// Over the pixels whose ray found a surface crossing (HitKind::Surface).
SurfaceError surfaceError(const ReferenceHits& hits, const AnalyticField& truth);

// The OpenCL kernel's hits (Raycaster::renderWithHits: xyz voxel position, w 1 crossing,
// 0 first sample, -1 none) as ReferenceHits without normals, so surfaceError scores the
// kernel's own hit points (its normal angles are then left out).
ReferenceHits kernelHits(const std::vector<glm::vec4>& hits, int width, int height);

// Distance (voxels) of each hit point to the hit point of the same pixel in `fine` (the
// same reconstruction marched at a tiny step with many bisections): the error of finding
// the crossing alone, without the reconstruction's own error. Pixels where either missed
// are left out; so are (counted in `excluded`) those more than sameCrossingVoxels apart:
// there the coarse march stepped over a thin feature and found another crossing, which no
// refinement can fix and which would swamp the refinement's error in the mean.
ErrorStats hitPointError(const ReferenceHits& hits, const ReferenceHits& fine,
                         double sameCrossingVoxels = 1e300);

}  // namespace voxray
