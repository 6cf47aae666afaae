#pragma once
// Undo/redo of what the user does to the view of a study: camera, clip box, light, the mip
// window, the slice window/level, and the slice views' turned planes and slabs (not where the
// crosshair is: moving through the slices is reading, not editing). It listens to the models,
// so every edit (mouse, panel, keys) is recorded without the widgets knowing. Appearance and
// quality are not recorded: they are choices made in the panel, where they stay visible, and
// quality is a preference. Opening a study starts a new history (that study's defaults are the
// first state).
#include <array>
#include <map>
#include <string>
#include <vector>

#include "app_models.h"
#include "no_qt.h"
#include "notifier.h"

namespace voxray {

// The recorded state.
struct ViewSnapshot {
  CameraParams camera;
  ClipBox clip;
  LightParams light;
  double mipWidth = 0.0, mipLevel = 0.0;
  WindowLevel wl;
  std::string wlSource;  // where the window came from ("DICOM window 1"), back with it on undo
  // The slice views' rotations and slabs by Orientation (CrosshairModel).
  std::array<glm::dmat3, 3> planes{glm::dmat3(1.0), glm::dmat3(1.0), glm::dmat3(1.0)};
  std::array<Slab, 3> slabs{};
  // The segments' own transfer functions (RenderParams::segmentTfs): an appearance, but chosen
  // per segment in the Segments panel, where a wrong pick is one Ctrl+Z away (issue 35).
  std::map<int, std::vector<ControlPoint>> segmentTfs{};
};
ViewSnapshot takeViewSnapshot(const AppModels& m);
bool sameView(const ViewSnapshot& a, const ViewSnapshot& b);

class ViewHistory {
 public:
  // Listens to M's render state, window/level and document until destroyed.
  explicit ViewHistory(AppModels& m);
  ~ViewHistory();
  ViewHistory(const ViewHistory&) = delete;
  ViewHistory& operator=(const ViewHistory&) = delete;

  // Every change between the two is one step (a drag, a slider pulled, a spin box held).
  // Unbalanced calls are harmless: an end without a begin does nothing.
  void beginGesture();
  void endGesture();

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  size_t undoCount() const { return undo_.size(); }  // the steps undo can take back
  size_t redoCount() const { return redo_.size(); }
  void undo();
  void redo();
  // How many steps are kept; the oldest go first.
  static constexpr size_t kLimit = 200;

  Notifier<> changed;  // canUndo or canRedo may have changed

 private:
  void onChange();
  void restart();
  void apply(const ViewSnapshot& s);
  // Moves the current state onto TO and goes back to the last of FROM.
  void step(std::vector<ViewSnapshot>& from, std::vector<ViewSnapshot>& to);

  AppModels& m_;
  ViewSnapshot current_;
  std::vector<ViewSnapshot> undo_, redo_;
  bool inGesture_ = false, gestureRecorded_ = false, applying_ = false;
  int renderConnection_ = 0, wlConnection_ = 0, docConnection_ = 0, crosshairConnection_ = 0;
};

}  // namespace voxray
