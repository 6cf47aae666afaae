#pragma once
// The Measurements side panel: the tool buttons, the list of measurements with their
// numbers (select one to edit it in the views, Del or the button removes it), and the
// check box that puts measurements into exported images (off by default). Below them the text
// and arrow annotations, each with its text (select one to highlight it; Delete removes it).
#include <QDockWidget>

#include "annotation_model.h"
#include "measurement_model.h"
#include "volume_document.h"

namespace voxray::ui {

QDockWidget* makeMeasurementDock(MeasurementModel& m, AnnotationModel& a, VolumeDocument& doc);

}  // namespace voxray::ui
