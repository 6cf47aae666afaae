#include "frame_setup.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/volume.h"

namespace voxray {

TransferFunction frameTransferFunction(const RenderParams& p) {
  auto shifted = [&](TransferFunction tf) {
    for (auto& c : tf.points) c.hu += p.presetShiftHu;
    return tf;
  };
  if (!p.transferFunction.empty()) return shifted(TransferFunction{p.transferFunction});
  if (!p.preset.empty()) {
    const Preset& preset = findPreset(p.preset);
    if (!preset.tf.points.empty()) return shifted(preset.tf);
  }
  if (p.mode == Mode::Dvr) return shifted(findPreset("CT-Bone").tf);
  // iso: a plain surface colour; mip does not use the table.
  glm::dvec4 c(p.surfaceColor, 1.0);
  return TransferFunction{{{0.0, c}}};
}

FrameSetup makeFrameSetup(const Volume& v, const RenderParams& p) {
  FrameSetup s;
  s.view = makeViewGeometry(v, p);
  s.lut = bakeLut(frameTransferFunction(p), v);
  double minSpacing = v.minSpacingMm();
  s.stepMm = effectiveStepMm(p, minSpacing);
  s.referenceStepMm = minSpacing;
  double a = v.toStored(p.isoLo), b = v.toStored(p.isoHi);
  s.isoLoStored = std::min(a, b);
  s.isoHiStored = std::max(a, b);
  ValueRange r = storedRange(v);
  double lo, width;
  if (p.windowWidth > 0.0) {
    width = p.windowWidth / std::abs(v.slope);
    lo = v.toStored(p.windowLevel) - 0.5 * width;
  } else {
    lo = r.min;
    width = std::max(1.0, double(r.max) - double(r.min));
  }
  s.windowLoStored = lo;
  s.windowInvWidth = 1.0 / width;
  return s;
}

}  // namespace voxray
