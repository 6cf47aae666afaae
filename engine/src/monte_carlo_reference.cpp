#include "voxray/engine/monte_carlo_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "frame_setup.h"
#include "reference_hooks.h"
#include "reference_sampling.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

constexpr double kMaxDepth = 40.0;  // exp(-40) < 5e-18: the rest of a ray cannot matter

// The estimators of the header's models on one frame's setup.
struct Estimators {
  const Volume& v;
  const RenderParams& p;
  FrameSetup s;
  glm::dmat3 voxelToWorld;
  double step, radius, shadowOffset = shadowOffsetMm(v);

  Estimators(const Volume& vol, const RenderParams& params, const MonteCarloOptions& o)
      : v(vol), p(params), s(makeFrameSetup(vol, params)) {
    voxelToWorld = glm::inverse(s.view.worldToVoxel);
    step = o.stepMm > 0.0 ? o.stepMm : s.stepMm;
    radius = o.aoRadiusMm;
    if (!(step > 0.0) || !std::isfinite(step) || !(radius > 0.0) || !std::isfinite(radius))
      throw inputError("the Monte Carlo step and occlusion radius must be positive mm");
  }

  double sigma(const glm::dvec3& pv) const {
    const double value = sampleVolume(v, p.interp, pv);
    double a = p.mode == Mode::Iso ? double(s.inIso(value)) : s.lut.lookup(value).a;
    a = std::clamp(a, 0.0, 1.0 - 1e-12);
    return -std::log1p(-a) / s.referenceStepMm;
  }

  // Stratified estimate of the optical depth from `world` along unit `dir`, from `skip` to
  // `length` mm, inside the clip box; u in [0, 1) is the realisation's offset.
  double depth(const glm::dvec3& world, const glm::dvec3& dir, double skip, double length,
               double u) const {
    glm::dvec3 ov = s.view.toVoxel(world), dv = s.view.dirToVoxel(dir);
    double t0, t1;
    int axis;
    if (!intersectBox(ov, dv, s.view.clipLo, s.view.clipHi, t0, t1, axis)) return 0.0;
    double a = std::max(t0, skip), b = std::min(t1, length);
    if (!(b > a)) return 0.0;
    double n = std::clamp(std::ceil((b - a) / step), 1.0, 1e7), h = (b - a) / n, sum = 0.0;
    for (double k = 0.0; k < n && sum * h < kMaxDepth; k += 1.0)
      sum += sigma(ov + (a + (k + u) * h) * dv);
    return sum * h;
  }

  double transmittanceToLight(const glm::dvec3& world, Rng& rng) const {
    glm::dvec3 to = s.view.lightWorld - world;
    double m = std::max({std::abs(to.x), std::abs(to.y), std::abs(to.z)});
    if (!(m > 1e-9) || !std::isfinite(m)) return 1.0;  // the light at the sample (or nowhere)
    glm::dvec3 scaled = to / m;
    double len = std::sqrt(glm::dot(scaled, scaled));
    double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    return std::exp(-depth(world, scaled / len, shadowOffset, m * len, u));
  }

  double visibility(const glm::dvec3& world, Rng& rng) const {
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    double z = 1.0 - 2.0 * uni(rng), phi = 2.0 * std::numbers::pi * uni(rng);
    double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    glm::dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
    return std::exp(-depth(world, w, 0.0, radius, uni(rng)));
  }

  LightParams light(const glm::dvec3& world, Rng& rng) const {
    LightParams k = p.light;
    if (p.lighting == Lighting::Shadows) {
      double t = transmittanceToLight(world, rng);
      k.diffuse *= t;
      k.specular *= t;
    } else if (p.lighting == Lighting::Ao) {
      k.ambient *= visibility(world, rng);
    }
    return k;
  }
};

void checkSamples(int samples) {
  if (samples < 2 || samples > 1000000)
    throw inputError("Monte Carlo samples must be 2 to 1000000 (a standard error needs two), not " +
                     std::to_string(samples));
}

template <class Draw>
Estimate estimate(int samples, uint64_t seed, Draw draw) {
  Rng rng(seed);
  double sum = 0.0, sq = 0.0;
  for (int i = 0; i < samples; ++i) {
    double x = draw(rng);
    sum += x;
    sq += x * x;
  }
  double n = double(samples), mean = sum / n;
  double var = std::max(0.0, (sq - sum * mean) / (n - 1.0));
  return {mean, std::sqrt(var / n)};
}

}  // namespace

int lightGridCell(const Volume& v) {
  constexpr int kMaxPoints = 128;  // 1.6 million points for a 512x512x400 CT (cells of 4)
  int largest = std::max({v.dims.x, v.dims.y, v.dims.z, 1});
  return std::max(1, (largest + kMaxPoints - 1) / kMaxPoints);
}

double shadowOffsetMm(const Volume& v) {
  double spacing = v.minSpacingMm();
  return spacing * (1.0 + 1.5 * lightGridCell(v));
}

double MonteCarloImage::meanStdError() const {
  double sum = 0.0;
  for (float e : stdError) sum += e;
  return stdError.empty() ? 0.0 : sum / double(stdError.size());
}

double MonteCarloImage::maxStdError() const {
  return stdError.empty() ? 0.0 : *std::max_element(stdError.begin(), stdError.end());
}

MonteCarloImage renderMonteCarlo(const Volume& v, const RenderParams& p,
                                 const MonteCarloOptions& o) {
  checkSamples(o.samples);
  if (p.lighting == Lighting::Cinematic)
    throw inputError(
        "the Monte Carlo reference renders phong, shadows and ao; cinematic has "
        "its own path-traced reference");
  Estimators lighting(v, p, o);
  ReferenceHooks hooks;
  hooks.light = [&](const glm::dvec3& w, Rng& rng) { return lighting.light(w, rng); };
  size_t values = size_t(p.width) * size_t(p.height) * 3;
  std::vector<double> sum(values, 0.0), sq(values, 0.0);
  for (int i = 0; i < o.samples; ++i) {
    hooks.stream = o.seed * 1000003ull + uint64_t(i);
    FloatImage f = renderReferenceFloat(v, p, nullptr, &hooks);
    for (size_t k = 0; k < values; ++k) {
      double x = f.rgb[k];
      sum[k] += x;
      sq[k] += x * x;
    }
  }
  MonteCarloImage out;
  out.samples = o.samples;
  out.mean.width = p.width;
  out.mean.height = p.height;
  out.mean.rgb.resize(values);
  out.stdError.assign(values / 3, 0.0f);
  double n = double(o.samples);
  for (size_t k = 0; k < values; ++k) {
    double mean = sum[k] / n, var = std::max(0.0, (sq[k] - sum[k] * mean) / (n - 1.0));
    out.mean.rgb[k] = float(mean);
    out.stdError[k / 3] = std::max(out.stdError[k / 3], float(std::sqrt(var / n)));
  }
  return out;
}

Estimate lightTransmittance(const Volume& v, const RenderParams& p, const glm::dvec3& world,
                            const MonteCarloOptions& o) {
  checkSamples(o.samples);
  Estimators lighting(v, p, o);
  return estimate(o.samples, o.seed,
                  [&](Rng& rng) { return lighting.transmittanceToLight(world, rng); });
}

Estimate ambientVisibility(const Volume& v, const RenderParams& p, const glm::dvec3& world,
                           const MonteCarloOptions& o) {
  checkSamples(o.samples);
  Estimators lighting(v, p, o);
  return estimate(o.samples, o.seed, [&](Rng& rng) { return lighting.visibility(world, rng); });
}

}  // namespace voxray
