#pragma once
// What the 3D view shows: the engine's RenderParams (declared once in render_params.h,
// shared with voxray-cli) plus the workstation's quality choices and the slice views'
// interpolation. Edits go through
// update() so every bound widget and the render scheduler hear about them.
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "adaptive_quality.h"
#include "notifier.h"
#include "view_overlays.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/volume_property.h"

namespace voxray {

enum Change : unsigned {
  kCamera = 1u << 0,
  kClip = 1u << 1,
  kLight = 1u << 2,
  kAppearance = 1u << 3,  // mode, preset, iso range, gradient, interpolation, colours
  kQuality = 1u << 4,     // resolution and quality preset
  kSlices = 1u << 5,      // the slice views' interpolation, the overlays: no new 3D frame
  kAll = 0x3fu,
};

constexpr double kPresetShiftLimitHu = 1000.0;
// The drag frame rate's range, for the spin box and saved preferences alike.
constexpr double kDragFpsMin = 5.0, kDragFpsMax = 60.0;
// The GPU memory budget's largest value in MiB (1 TiB), for the spin box and saved preferences.
constexpr int kGpuBudgetMibMax = 1 << 20;

struct Quality {
  glm::ivec2 resolution{0, 0};  // {0, 0} = the view's size (the "window size" choice)
  // The quality preset (resources/quality) of the frames once the mouse rests: its step,
  // refinement, jitter and image scale. Empty = custom: the render parameters' own step,
  // refinement and jitter. Frames while dragging use kDragQualityPreset whatever this is.
  std::string preset = "balanced";
  // Frames per second that drag frames adapt their size and step to hold (AdaptiveQuality).
  double dragFps = 20.0;
  // The "GPU memory budget" in MiB (issue 38): a study larger than it is drawn out of core
  // (out_of_core_view.h); 0: automatic, out of core only when it does not fit the device.
  int gpuBudgetMib = 0;
};

// The look a first start opens with, before any preference is saved (issue 41 item 6): dvr
// with CT-Bone, trilinear, Zucker-Hummel, half-voxel steps and jitter, under the custom
// quality. The sample CT's 5 mm slices made the old default (a 400 HU iso surface at the
// balanced preset's 1.5-voxel steps) striped and holed where the thin skull falls below the
// threshold between slices, and dvr at 1.5-voxel steps showed wood-grain rings; this look
// closes the skull and smooths the rings, at about 3x balanced's kernel time for a still
// (drags keep the interactive preset).
RenderParams firstStartLook();

class RenderStateModel {
 public:
  // firstStartLook() under the custom quality (its step and jitter are no preset's).
  RenderStateModel();

  const RenderParams& params() const { return params_; }
  const Quality& quality() const { return quality_; }

  // Applies EDIT and notifies with WHAT (bits of Change). An edit that changes the mode
  // drops a transfer-function preset made for another mode (and its shift and custom
  // table): the mode's default is what renders then, and what the preset box says.
  void update(unsigned what, const std::function<void(RenderParams&)>& edit);
  // Throws Error (Input) for an unknown quality preset, leaving the quality as it was.
  void setQuality(const Quality& q);
  // Picks a quality preset ("" = custom) and, for a preset, the reconstruction and gradient
  // it was measured with (the Rendering group may change them afterwards). Throws as above.
  void setQualityPreset(const std::string& name);
  // Selects a transfer-function preset by name (applyPreset: mode, iso range, window).
  // The preset shift goes back to 0: a shift tuned for one preset means nothing for another.
  void applyPreset(const std::string& name);  // throws Error (Input) for an unknown name
  // Moves the preset's transfer function along HU (the seed's shift slider), clamped to
  // +-kPresetShiftLimitHu so that a slider and saved state agree on the range.
  void setPresetShift(double hu);
  // How the slice views reconstruct between voxels (linear unless the user picks nearest).
  Interp sliceInterp() const { return sliceInterp_; }
  void setSliceInterp(Interp i);  // notifies kSlices
  // Whether the views show the patient and study corner text (study_text.h). Off at every
  // start: it identifies the patient, so it is shown only while the user asks for it.
  bool studyText() const { return studyText_; }
  void setStudyText(bool on);  // notifies kSlices (the views redraw; no new 3D frame)
  // What the 3D view draws over its image (view_overlays.h); saved in sessions.
  const ViewOverlays& overlays() const { return overlays_; }
  // The transfer function the editor shaped (its two lists and curve), while the view's
  // table is still the one it makes; none once a preset or another table replaced it.
  std::optional<VolumeProperty> shapedTransferFunction() const;
  void setShapedTransferFunction(std::optional<VolumeProperty> vp);  // no notification
  void setOverlays(const ViewOverlays& o);  // notifies kSlices (a redraw, no new 3D frame)
  // Values by key from the command line, as voxray-cli reads them (applyRenderValues: a
  // preset first, then the values given); --size picks the resolution, and an explicit
  // step, refinement or jitter switches the quality preset to custom so that it wins.
  // Throws Error (Input), leaving the state as it was.
  void applyValues(const std::map<std::string, std::string>& values);

  // Saved state: the engine's key=value text plus the quality keys.
  std::string toText() const;
  void fromText(const std::string& text);  // unknown or bad lines are skipped

  Notifier<unsigned> changed;

 private:
  RenderParams params_;
  Quality quality_;
  Interp sliceInterp_ = Interp::Linear;
  bool studyText_ = false;
  ViewOverlays overlays_;
  std::optional<VolumeProperty> shaped_;
};

// Whether the transfer-function preset PRESET (by its exact name) was made for MODE; false
// for an unknown name.
bool presetFitsMode(const std::string& preset, Mode mode);

// The parameters of one frame: the size from the quality choice (or the view size), then
// while INTERACTIVE everything the drag preset sets (step, reconstruction, gradient,
// refinement, jitter, image scale); otherwise the chosen preset's step, refinement, jitter
// and image scale with the user's reconstruction and gradient, or for custom the
// parameters as they are. minSpacingMm: the volume's smallest voxel spacing. DRAG: the
// image scale and step of an interactive frame in place of the drag preset's (the
// AdaptiveQuality controller's choice).
RenderParams planFrame(const RenderParams& base, const Quality& q, const glm::ivec2& viewSize,
                       bool interactive, double minSpacingMm, const DragSetting* drag = nullptr);
// The drag preset's own scale and step: where AdaptiveQuality starts.
DragSetting dragPresetSetting();
// The setting a drag FRAME (planFrame's) was rendered with, read back from its width (of
// the full frame's FULLWIDTH) and step, as AdaptiveQuality::record takes it.
DragSetting dragSettingOf(const RenderParams& frame, int fullWidth, double minSpacingMm);

}  // namespace voxray
