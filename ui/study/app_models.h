#pragma once
// All UI state of one workstation window, owned outside the widgets so that it outlives
// them (widgets disconnect from the models when they are destroyed).
#include <optional>
#include <string>
#include "annotation_model.h"
#include "crosshair_model.h"
#include "fusion.h"
#include "lighting_figures.h"
#include "measurement_model.h"

#include "no_qt.h"
#include "render_state_model.h"
#include "segment_tools.h"
#include "segmentation_model.h"
#include "session.h"
#include "time_series.h"
#include "volume_document.h"
#include "window_level.h"

namespace voxray {

struct AppModels {
  VolumeDocument document;
  RenderStateModel render;
  WindowLevelModel windowLevel;
  CrosshairModel crosshair;
  MeasurementModel measurements;   // a session keeps them (session_state.cpp)
  AnnotationModel annotations;     // text and arrows in the slice views; a session keeps them
  SegmentationModel segmentation;  // the segment editor's; a session keeps it too
  SegmentToolModel segmentTools;   // the editor's tool and its settings (not saved)
  TimePlayer player;               // a 4D series' play rate and state (the document: its point)
  FusionModel fusion;              // issue 36: a second volume over the slices and in 3D
  // Compare (issue 36): the prior beside the study and its alignment, for a session to keep;
  // a session read sets it and the window opens the prior (none: no comparison).
  std::optional<Session::Comparison> comparison;
  LightingFigures lighting;  // each lighting model's cost and error on this scene
  // Where the document's volume came from (path and input flags), for a session to save.
  SessionInput source;
  // While a volume whose values are not HU is open (value_look.h): the user's HU look
  // (preferencesText), saved as the preferences and put back when a CT opens.
  std::optional<std::string> huLook;
  // The OpenCL selector the window renders with ("": $VOXRAY_DEVICE or auto), for the
  // contexts of its own of a movie export or a lighting measurement.
  std::string device;

  // The per-study state of the volume the document keeps as its previous one: openStudy
  // saves it, restorePreviousStudy (study_state.h) brings it back with that volume.
  struct PreviousStudy {
    bool valid = false;
    RenderParams render;
    WindowLevel wl;
    std::string wlSource;
    glm::ivec3 dims{1}, crosshair{0};
    SessionInput source;
    glm::dvec3 spacingMm{1.0};  // the crosshair's geometry (oblique planes turn in mm)
    glm::dmat3 direction{1.0};
  } previousStudy;
};

}  // namespace voxray
