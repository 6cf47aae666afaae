#include "render_state_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "quality_choice.h"
#include "voxray/engine/quality.h"
#include "voxray/engine/step.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"

namespace voxray {

bool presetFitsMode(const std::string& preset, Mode mode) {
  for (const Preset& p : builtinPresets())
    if (p.name == preset) return parseMode(p.mode) == mode;
  return false;
}

RenderParams firstStartLook() {
  RenderParams p;
  applyPreset(p, findPreset("CT-Bone"));
  p.interp = Interp::Linear;
  p.gradient = Gradient::ZuckerHummel;
  p.stepMm = 0.0;  // half the smallest spacing (step.h)
  p.jitter = true;
  return p;
}

RenderStateModel::RenderStateModel() : params_(firstStartLook()) { quality_.preset.clear(); }

void RenderStateModel::update(unsigned what, const std::function<void(RenderParams&)>& edit) {
  Mode before = params_.mode;
  edit(params_);
  if (params_.mode != before && !params_.preset.empty() &&
      !presetFitsMode(params_.preset, params_.mode)) {
    params_.preset.clear();
    params_.transferFunction.clear();
    params_.presetShiftHu = 0.0;
  }
  changed.notify(what);
}

void RenderStateModel::setQuality(const Quality& q) {
  if (!q.preset.empty()) findQualityPreset(q.preset);  // throws for an unknown name
  quality_ = q;
  changed.notify(kQuality);
}

void RenderStateModel::setSliceInterp(Interp i) {
  sliceInterp_ = i;
  changed.notify(kSlices);
}

void RenderStateModel::setStudyText(bool on) {
  studyText_ = on;
  changed.notify(kSlices);
}

std::optional<VolumeProperty> RenderStateModel::shapedTransferFunction() const {
  if (!shaped_ || !params_.preset.empty() || params_.transferFunction != renderTable(*shaped_))
    return std::nullopt;
  return shaped_;
}

void RenderStateModel::setShapedTransferFunction(std::optional<VolumeProperty> vp) {
  shaped_ = std::move(vp);
}

void RenderStateModel::setOverlays(const ViewOverlays& o) {
  if (o == overlays_) return;
  overlays_ = o;
  changed.notify(kSlices);
}

void RenderStateModel::setQualityPreset(const std::string& name) {
  Quality q = quality_;
  q.preset = name;
  if (name.empty()) {
    setQuality(q);
    return;
  }
  const QualityPreset& preset = findQualityPreset(name);
  q.preset = preset.name;
  quality_ = q;
  update(kQuality | kAppearance, [&](RenderParams& p) { p = pickQualityPreset(p, preset); });
}

void RenderStateModel::applyPreset(const std::string& name) {
  const Preset& preset = findPreset(name);
  update(kAppearance, [&](RenderParams& p) {
    voxray::applyPreset(p, preset);
    // A preset chosen in the workstation is what the view shows: a 2D transfer function
    // would replace its table in dvr (tf2d.h), so it goes. (The CLI applies its preset first
    // and its --tf2d after, so there they combine.)
    p.tf2d = {};
  });
}

void RenderStateModel::applyValues(const std::map<std::string, std::string>& values) {
  RenderParams p = params_;
  applyRenderValues(p, values);
  Quality q = quality_;
  if (values.count("size")) q.resolution = {p.width, p.height};
  p.width = params_.width;  // the view decides the size; --size is the resolution choice
  p.height = params_.height;
  for (const char* key : {"step", "refine", "jitter"})
    if (values.count(key)) q.preset.clear();
  params_ = p;
  quality_ = q;
  changed.notify(kAll);
}

void RenderStateModel::setPresetShift(double hu) {
  double clamped = std::clamp(hu, -kPresetShiftLimitHu, kPresetShiftLimitHu);
  update(kAppearance, [clamped](RenderParams& p) { p.presetShiftHu = clamped; });
}

std::string RenderStateModel::toText() const {
  std::ostringstream out;
  out << voxray::toText(params_);
  out << "ui-resolution=" << quality_.resolution.x << "," << quality_.resolution.y << "\n";
  out << "ui-quality=" << quality_.preset << "\n";
  out << "ui-slice-interp=" << voxray::toString(sliceInterp_) << "\n";
  out << "ui-drag-fps=" << quality_.dragFps << "\n";
  out << "ui-gpu-budget-mib=" << quality_.gpuBudgetMib << "\n";
  return out.str();
}

void RenderStateModel::fromText(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  RenderParams p = params_;
  Quality q = quality_;
  Interp sliceInterp = sliceInterp_;
  while (std::getline(in, line)) {
    auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    try {
      if (key == "ui-resolution") {
        std::sscanf(value.c_str(), "%d,%d", &q.resolution.x, &q.resolution.y);
      } else if (key == "ui-quality") {
        if (!value.empty()) findQualityPreset(value);  // throws for an unknown name
        q.preset = value;
      } else if (key == "ui-slice-interp") {
        sliceInterp = parseInterp(value);
      } else if (key == "ui-drag-fps") {
        const double fps = std::stod(value);
        if (std::isfinite(fps)) q.dragFps = std::clamp(fps, kDragFpsMin, kDragFpsMax);
      } else if (key == "ui-gpu-budget-mib") {
        q.gpuBudgetMib = std::clamp(std::stoi(value), 0, kGpuBudgetMibMax);
      } else if (key == "size" || key == "ui-step-scale") {
        // The view decides the size; ui-step-scale was an older version's quality.
      } else {
        voxray::fromText(p, line);
      }
    } catch (const std::exception&) {
      // Saved state from another version: keep the current value for this key.
    }
  }
  p.presetShiftHu = std::clamp(p.presetShiftHu, -kPresetShiftLimitHu, kPresetShiftLimitHu);
  params_ = p;
  sliceInterp_ = sliceInterp;
  setQuality(q);
  changed.notify(kAll);
}

RenderParams planFrame(const RenderParams& base, const Quality& q, const glm::ivec2& viewSize,
                       bool interactive, double minSpacingMm, const DragSetting* drag) {
  if (!interactive) return settledFrame(base, q.preset, q.resolution, viewSize, minSpacingMm);
  QualityPreset dragPreset = findQualityPreset(kDragQualityPreset);
  if (drag) {
    dragPreset.resolutionScale = drag->scale;
    dragPreset.stepVoxels = drag->stepVoxels;
  }
  // The custom frame at full size, then the drag preset's (or controller's) scale and step.
  RenderParams p = applyQuality(settledFrame(base, "", q.resolution, viewSize, minSpacingMm),
                                dragPreset, minSpacingMm);
  // Speed comes from the step and the size; the surfaces keep the user's look, so the
  // shading does not change the moment the camera moves.
  p.interp = base.interp;
  p.gradient = base.gradient;
  p.width = std::max(p.width, 16);
  p.height = std::max(p.height, 16);
  return p;
}

DragSetting dragPresetSetting() {
  const QualityPreset& q = findQualityPreset(kDragQualityPreset);
  return {q.resolutionScale, q.stepVoxels};
}

DragSetting dragSettingOf(const RenderParams& frame, int fullWidth, double minSpacingMm) {
  return {double(frame.width) / std::max(fullWidth, 1), stepVoxelsOf(frame.stepMm, minSpacingMm)};
}

}  // namespace voxray
