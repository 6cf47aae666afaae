#pragma once
// The side panel: groups of controls, each bound to the models by couplings. Building each
// group is its own function (panel_*.cpp) so the files stay small.
#include <QCheckBox>
#include <QGroupBox>
#include <QScrollArea>

#include "app_models.h"

namespace voxray::ui {

// DOC: the open volume, whose unit the value controls show (HU for a CT).
QGroupBox* makeRenderGroup(RenderStateModel& m, VolumeDocument& doc);
QGroupBox* makeQualityGroup(RenderStateModel& m);
QGroupBox* makeCameraGroup(RenderStateModel& m);
QGroupBox* makeClipGroup(AppModels& models);
QGroupBox* makeLightGroup(AppModels& models);
QGroupBox* makeSliceGroup(WindowLevelModel& wl, RenderStateModel& state, VolumeDocument& doc);
QGroupBox* makeMprGroup(CrosshairModel& crosshair, RenderStateModel& state);  // panel_mpr.cpp

// A check box named NAME bound both ways to one of the 3D view's overlays (a session sets
// them too). In panel_mpr.cpp.
QCheckBox* makeOverlayCheck(RenderStateModel& m, bool ViewOverlays::*field, const QString& text,
                            const QString& name, const QString& tooltip);

// All groups in a scrollable column.
QScrollArea* makeControlPanel(AppModels& models);

}  // namespace voxray::ui
