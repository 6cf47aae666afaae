#pragma once
// All UI state of one workstation window, owned outside the widgets so that it outlives
// them (widgets disconnect from the models when they are destroyed).
#include "crosshair_model.h"
#include "no_qt.h"
#include "render_state_model.h"
#include "volume_document.h"
#include "window_level.h"

namespace voxray::ui {

struct AppModels {
  VolumeDocument document;
  RenderStateModel render;
  WindowLevelModel windowLevel;
  CrosshairModel crosshair;
};

}  // namespace voxray::ui
