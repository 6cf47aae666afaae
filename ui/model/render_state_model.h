#pragma once
// What the 3D view shows: the engine's RenderParams (declared once in render_params.h,
// shared with voxray-cli) plus the workstation's quality choices. Edits go through
// update() so every bound widget and the render scheduler hear about them.
#include <functional>
#include <string>

#include "notifier.h"
#include "voxray/engine/render_params.h"

namespace voxray::ui {

enum Change : unsigned {
  kCamera = 1u << 0,
  kClip = 1u << 1,
  kLight = 1u << 2,
  kAppearance = 1u << 3,  // mode, preset, iso range, gradient, interpolation, colours
  kQuality = 1u << 4,     // resolution and step
  kAll = 0x1fu,
};

constexpr double kPresetShiftLimitHu = 1000.0;

struct Quality {
  glm::ivec2 resolution{0, 0};  // {0, 0} = the view's size (the "window size" choice)
  double stepScale = 1.0;       // times the engine's default step: 0.5 = finer, 2 = faster
  // While the user drags, frames are rendered at 1/interactiveDivisor of the size with
  // interactiveStepScale times the step, then refined when the mouse stops.
  int interactiveDivisor = 2;
  double interactiveStepScale = 2.0;
};

class RenderStateModel {
 public:
  const RenderParams& params() const { return params_; }
  const Quality& quality() const { return quality_; }

  // Applies EDIT and notifies with WHAT (bits of Change).
  void update(unsigned what, const std::function<void(RenderParams&)>& edit);
  void setQuality(const Quality& q);
  // Selects a transfer-function preset by name (applyPreset: mode, iso range, window).
  // The preset shift goes back to 0: a shift tuned for one preset means nothing for another.
  void applyPreset(const std::string& name);  // throws Error (Input) for an unknown name
  // Moves the preset's transfer function along HU (the seed's shift slider), clamped to
  // +-kPresetShiftLimitHu so that a slider and saved state agree on the range.
  void setPresetShift(double hu);

  // Saved state: the engine's key=value text plus the quality keys.
  std::string toText() const;
  void fromText(const std::string& text);  // unknown or bad lines are skipped

  Notifier<unsigned> changed;

 private:
  RenderParams params_;
  Quality quality_;
};

// The parameters of one frame: resolution from the quality choice (or the view size),
// and cheaper resolution and step while INTERACTIVE. minSpacingMm: the volume's smallest
// voxel spacing (for the default step).
RenderParams planFrame(const RenderParams& base, const Quality& q, const glm::ivec2& viewSize,
                       bool interactive, double minSpacingMm);

}  // namespace voxray::ui
