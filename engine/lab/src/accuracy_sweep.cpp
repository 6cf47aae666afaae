#include "voxray/lab/accuracy_sweep.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "voxray/engine/cl_context.h"
#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/monte_carlo_reference.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/step.h"
#include "voxray/io/statistics.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

struct Fine {
  FloatImage image;
  ReferenceHits hits;
};

}  // namespace

RenderParams fineParams(RenderParams p, Interp interp, double stepMm, int refine) {
  p.interp = interp;
  p.stepMm = stepMm;
  p.refine = refine;
  p.jitter = false;
  p.opacityCorrection = true;
  return p;
}

std::string settingLabel(const RenderParams& p, double minSpacingMm) {
  std::ostringstream s;
  // The kernel variant's name says what the kernel switches say (no gradient for mip, ...).
  s << "step=" << stepVoxelsOf(p.stepMm, minSpacingMm) << " " << kernelVariantName(p) << " "
    << p.width << "x" << p.height;
  return s.str();
}

std::vector<SweepCase> standardCases(const SweepScene& scene, bool reduced) {
  const double h = scene.volume->minSpacingMm();
  std::vector<RenderParams> list;
  auto with = [&](double stepVoxels, auto&& change) {
    RenderParams p = scene.base;
    p.stepMm = stepMmOf(stepVoxels, h);
    p.interp = Interp::Linear;
    p.gradient = Gradient::ZuckerHummel;
    p.refine = 4;
    change(p);
    list.push_back(p);
  };
  auto none = [](RenderParams&) {};
  const std::vector<double> steps =
      reduced ? std::vector<double>{0.5, 2.0} : std::vector<double>{0.125, 0.25, 0.5, 1, 2, 4};
  for (double s : steps) with(s, none);
  with(0.5, [](RenderParams& p) { p.interp = Interp::Nearest; });
  if (scene.base.mode != Mode::Mip)
    for (Gradient g : {Gradient::Central, Gradient::Sobel})
      with(0.5, [g](RenderParams& p) { p.gradient = g; });
  if (reduced) {
  } else if (scene.base.mode == Mode::Iso) {
    for (int r = 0; r <= 8; ++r) with(1.0, [r](RenderParams& p) { p.refine = r; });
    with(1.0, [](RenderParams& p) { p.jitter = true; });
  } else if (scene.base.mode == Mode::Dvr) {
    for (double s : {1.0, 2.0}) with(s, [](RenderParams& p) { p.jitter = true; });
    with(2.0, [](RenderParams& p) { p.opacityCorrection = false; });
    with(1.5, [](RenderParams&) {});  // between the presets' candidates
    // Half the resolution: a quarter of the rays (the interactive-drag trade).
    for (double s : {1.0, 2.0})
      with(s, [](RenderParams& p) {
        p.width /= 2;
        p.height /= 2;
      });
  }
  std::vector<SweepCase> cases;
  for (const RenderParams& p : list) {
    std::string label = settingLabel(p, h);
    bool seen = std::any_of(cases.begin(), cases.end(),
                            [&](const SweepCase& c) { return c.setting == label; });
    if (!seen) cases.push_back({label, p});
  }
  return cases;
}

std::vector<SweepRow> runSweep(ClContext& ctx, const SweepScene& scene,
                               const std::vector<SweepCase>& cases, const SweepOptions& o) {
  const Volume& v = *scene.volume;
  const double h = v.minSpacingMm();
  Raycaster rc(ctx, v, VolumeStorage::Auto);
  std::map<std::string, Fine> fine;
  auto fineFor = [&](const RenderParams& p, Interp interp) -> const Fine& {
    // The same operator, trilinear (images) or the case's own reconstruction (hit points).
    RenderParams f = fineParams(p, interp, stepMmOf(o.fineStepVoxels, h), o.fineRefine);
    std::string key = toText(f);
    auto it = fine.find(key);
    if (it != fine.end()) return it->second;
    if (o.progress) o.progress(scene.name + ": fine reference " + settingLabel(f, h));
    Fine r;
    r.image = renderReferenceFloat(v, f, &r.hits);
    if (f.lighting == Lighting::Shadows || f.lighting == Lighting::Ao) {
      // Their ground truth is the Monte Carlo reference (the hits stay the plain one's:
      // lighting moves no surface). Shadow and occlusion rays at half a voxel.
      MonteCarloOptions mc;
      mc.samples = 4;
      mc.stepMm = stepMmOf(0.5, h);
      r.image = renderMonteCarlo(v, f, mc).mean;
    }
    return fine.emplace(key, std::move(r)).first->second;
  };

  std::vector<SweepRow> rows;
  for (const SweepCase& c : cases) {
    if (o.progress) o.progress(scene.name + ": " + c.setting);
    SweepRow row;
    row.scene = scene.name;
    row.setting = c.setting;
    row.mode = c.params.mode;
    Image img;
    std::vector<double> ms;
    for (int i = -1; i < std::max(1, o.frames); ++i) {
      FrameStats st;
      rc.render(c.params, img, &st);
      if (i >= 0) ms.push_back(st.totalMs);  // frame -1 builds the kernel
    }
    row.msPerFrame = median(ms);
    ReferenceHits hits;
    renderReferenceFloat(v, c.params, &hits);
    row.samplesPerSecond = row.msPerFrame > 0.0 ? hits.samples / (row.msPerFrame * 1e-3) : 0.0;

    // Image error at the reference's resolution (a half-size frame is upscaled first).
    RenderParams full = c.params;
    full.width = scene.base.width;
    full.height = scene.base.height;
    const Fine& fi = fineFor(full, Interp::Linear);
    FloatImage test = toFloatImage(img);
    if (test.width != fi.image.width) {
      FloatImage up = fi.image;
      for (int y = 0; y < up.height; ++y)
        for (int x = 0; x < up.width; ++x) {
          int sx = std::min(test.width - 1, x * test.width / up.width);
          int sy = std::min(test.height - 1, y * test.height / up.height);
          for (int k = 0; k < 3; ++k)
            up.rgb[(size_t(y) * up.width + x) * 3 + k] =
                test.rgb[(size_t(sy) * test.width + sx) * 3 + k];
        }
      test = std::move(up);
    }
    row.image = compareImages(test, fi.image);
    if (c.params.mode == Mode::Iso && c.params.width == scene.base.width) {
      // A crossing more than one step from the fine one is a different crossing.
      row.hitPoint = hitPointError(hits, fineFor(c.params, c.params.interp).hits,
                                   stepVoxelsOf(c.params.stepMm, h));
      if (scene.truth) {
        row.hasSurface = true;
        row.surface = surfaceError(hits, *scene.truth);
        std::vector<glm::vec4> kernel;  // an extra, untimed frame: HIT_OUTPUT is a variant
        rc.renderWithHits(c.params, kernel);
        row.kernelSurface =
            surfaceError(kernelHits(kernel, c.params.width, c.params.height), *scene.truth)
                .positionVoxels;
      }
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<bool> paretoFront(const std::vector<double>& ms, const std::vector<double>& error) {
  std::vector<bool> front(ms.size(), true);
  for (size_t i = 0; i < ms.size(); ++i)
    for (size_t j = 0; j < ms.size() && front[i]; ++j)
      if (j != i && ms[j] <= ms[i] && error[j] <= error[i] &&
          (ms[j] < ms[i] || error[j] < error[i]))
        front[i] = false;
  return front;
}

}  // namespace voxray
