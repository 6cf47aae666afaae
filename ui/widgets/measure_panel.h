#pragma once
// The Measurements side panel: the tool buttons, the list of measurements with their
// numbers (select one to edit it in the views, Del or the button removes it), and the
// check box that puts measurements into exported images (off by default).
#include <QDockWidget>

#include "measurement_model.h"
#include "volume_document.h"

namespace voxray::ui {

QDockWidget* makeMeasurementDock(MeasurementModel& m, VolumeDocument& doc);

}  // namespace voxray::ui
