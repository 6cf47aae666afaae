#pragma once
// The side panel: groups of controls, each bound to the models by couplings. Building each
// group is its own function (panel_*.cpp) so the files stay small.
#include <QGroupBox>
#include <QScrollArea>

#include "app_models.h"

namespace voxray::ui {

class VolumeView;

QGroupBox* makeRenderGroup(RenderStateModel& m);
QGroupBox* makeQualityGroup(RenderStateModel& m);
QGroupBox* makeCameraGroup(RenderStateModel& m);
QGroupBox* makeClipGroup(AppModels& models, VolumeView& view);
QGroupBox* makeLightGroup(AppModels& models, VolumeView& view);
QGroupBox* makeSliceGroup(WindowLevelModel& wl, RenderStateModel& state);
QGroupBox* makeMprGroup(CrosshairModel& crosshair, VolumeView& view);  // panel_mpr.cpp

// All groups in a scrollable column.
QScrollArea* makeControlPanel(AppModels& models, VolumeView& view);

}  // namespace voxray::ui
