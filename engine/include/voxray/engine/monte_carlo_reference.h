#pragma once
// The Monte Carlo reference for the lighting models beyond Phong (issue 15), in double
// precision on the host: the reference renderer's algorithm (reference_renderer.h), run
// `samples` times with a random jitter per pixel and the lighting of each shaded sample
// estimated by random quadrature, averaged, with each pixel's standard error of the mean.
//
// The models, for a sample at x shaded with the frame's Blinn-Phong coefficients
// (ambient ka, diffuse kd, specular ks):
//   phong    ka + kd (n.l) + ks (n.h)^s, as the reference renderer.
//   shadows  single scattering of the point light: kd and ks scaled by the transmittance
//            T(x) = exp(-integral of sigma along the segment toward the light from
//            shadowOffsetMm() past x to the light), inside the clip box only (what is
//            clipped away casts no shadow). The offset (the usual shadow bias) keeps an
//            opaque surface from shadowing itself: a sample just inside it would otherwise
//            see the light through the surface's own voxels.
//   ao       ka scaled by the ambient visibility A(x) = mean over all directions w of the
//            sphere of exp(-integral of sigma from x to x + R w) (local ambient occlusion of
//            Hernell et al. 2010, spherical: it needs no surface normal, so it is defined in
//            a uniform medium too); R = aoRadiusMm. Closed form at height h above an opaque
//            half-space, h < R: A = (1 + h / R) / 2.
// sigma, the extinction per mm of the classified volume, follows the kernels' opacity
// correction: a sample of opacity a per reference step r has sigma = -ln(1 - a) / r
// (a is capped at 1 - 1e-12, so an opaque region has T about 1e-12 per reference step).
// In iso frames a is the surface's: 1 in the iso range, 0 outside it (iso's table gives
// every value the surface colour at opacity 1, air too).
// Each optical depth is a stratified estimate (one random offset, step stepMm); exp() of it
// has a bias of the order of its variance, which vanishes with the step (exact in a medium
// uniform along the ray). Shadow and occlusion rays stop once the depth passes 40 (T < 5e-18).
#include <cstdint>
#include <vector>

#include "voxray/engine/reference_renderer.h"
#include "voxray/engine/render_params.h"

namespace voxray {

struct Volume;

// The occlusion radius of `ao`, in mm (kernels and reference).
constexpr double kAoRadiusMm = 10.0;

// The kernels' light grid (engine/src/light_volume.h) has a point every lightGridCell()
// voxels: at most 128 per axis.
int lightGridCell(const Volume& v);
// The shadows model's offset: one reference step (the smallest spacing) plus 1.5 light grid
// cells, so that the grid's interpolation across a surface does not shadow it either.
double shadowOffsetMm(const Volume& v);

struct MonteCarloOptions {
  int samples = 64;  // independent realisations per pixel
  uint64_t seed = 1;
  double aoRadiusMm = kAoRadiusMm;
  double stepMm = 0.0;  // quadrature step of shadow and occlusion rays; 0: the frame's step
};

struct MonteCarloImage {
  FloatImage mean;
  std::vector<float> stdError;  // per pixel: the largest channel's standard error of the mean
  int samples = 0;
  double meanStdError() const;
  double maxStdError() const;
};

MonteCarloImage renderMonteCarlo(const Volume& v, const RenderParams& p,
                                 const MonteCarloOptions& o = {});

struct Estimate {
  double mean = 0.0, stdError = 0.0;
};
// T(x) and A(x) at one point (LPS mm in the frame's world: relative to the volume centre),
// from o.samples independent estimates.
Estimate lightTransmittance(const Volume& v, const RenderParams& p, const glm::dvec3& world,
                            const MonteCarloOptions& o = {});
Estimate ambientVisibility(const Volume& v, const RenderParams& p, const glm::dvec3& world,
                           const MonteCarloOptions& o = {});

}  // namespace voxray
