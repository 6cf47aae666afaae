#include "frame_setup.h"

#include <algorithm>
#include <cmath>

#include "voxray/engine/step.h"
#include "voxray/io/volume.h"

namespace voxray {

SetupKey setupKeyOf(const RenderParams& p) {
  // Only dvr renders the gradient opacity (kernelSwitches' GRADIENT_OPACITY): elsewhere no
  // table is made for it, so none rides in the table buffer.
  // The 2D transfer function replaces the gradient opacity (tf2d.h), so that one is not kept.
  std::vector<glm::dvec2> gradientOpacity;
  Tf2d tf2d;
  if (p.mode == Mode::Dvr) {
    tf2d = p.tf2d;
    if (tf2d.empty()) gradientOpacity = p.gradientOpacity;
  }
  return {p.mode,
          p.preset,
          p.presetShiftHu,
          p.transferFunction,
          p.opacityUnitMm,
          gradientOpacity,
          tf2d,
          p.surfaceColor,
          p.isoLo,
          p.isoHi,
          p.windowWidth,
          p.windowLevel};
}

TransferFunction frameTransferFunction(const SetupKey& k) {
  auto shifted = [&](TransferFunction tf) {
    for (auto& c : tf.points) c.hu += k.presetShiftHu;
    return tf;
  };
  if (!k.transferFunction.empty()) return shifted(TransferFunction{k.transferFunction});
  if (!k.preset.empty()) {
    const Preset& preset = findPreset(k.preset);
    if (!preset.tf.points.empty()) return shifted(preset.tf);
  }
  if (k.mode == Mode::Dvr) return shifted(findPreset("CT-Bone").tf);
  // iso: a plain surface colour; mip does not use the table.
  glm::dvec4 c(k.surfaceColor, 1.0);
  return TransferFunction{{{0.0, c}}};
}

TransferFunction frameTransferFunction(const RenderParams& p) {
  return frameTransferFunction(setupKeyOf(p));
}

FrameSetup makeValueSetup(const Volume& v, const SetupKey& k) {
  return makeValueSetup(v, k, storedRange(v));
}

FrameSetup makeValueSetup(const Volume& v, const SetupKey& k, const ValueRange& r) {
  FrameSetup s;
  s.lut = bakeLut(frameTransferFunction(k), v, r);
  s.gradient = bakeGradientTable(k.gradientOpacity, v.slope);
  s.tf2d = bakeTf2dTable(k.tf2d, v);
  s.referenceStepMm = v.minSpacingMm();
  // Opacities stated per another length become per reference step: the same absorption
  // over the same millimetres, 1 - (1 - a)^(reference / unit).
  if (k.opacityUnitMm > 0.0 && k.opacityUnitMm != s.referenceStepMm) {
    double e = s.referenceStepMm / k.opacityUnitMm;
    for (std::vector<glm::vec4>* table : {&s.lut.rgba, &s.tf2d.rgba})
      for (glm::vec4& c : *table)
        if (c.a < 1.0f) c.a = float(1.0 - std::pow(1.0 - double(c.a), e));
  }
  reduceTf2dToLut(s.tf2d, s.lut);  // no-op without a 2D transfer function
  double a = v.toStored(k.isoLo), b = v.toStored(k.isoHi);
  s.isoLoStored = std::min(a, b);
  s.isoHiStored = std::max(a, b);
  double lo, width;
  if (k.windowWidth > 0.0) {
    width = k.windowWidth / std::abs(v.slope);
    lo = v.toStored(k.windowLevel) - 0.5 * width;
  } else {
    lo = r.min;
    width = std::max(1.0, double(r.max) - double(r.min));
  }
  s.windowLoStored = lo;
  s.windowInvWidth = 1.0 / width;
  return s;
}

void placeFrame(FrameSetup& s, const Volume& v, const RenderParams& p) {
  s.view = makeViewGeometry(v, p);
  s.stepMm = effectiveStepMm(p, s.referenceStepMm);
}

FrameSetup makeFrameSetup(const Volume& v, const RenderParams& p) {
  FrameSetup s = makeValueSetup(v, setupKeyOf(p));
  placeFrame(s, v, p);
  return s;
}

}  // namespace voxray
