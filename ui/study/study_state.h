#pragma once
// What persists and what belongs to the study on screen, declared once.
//
// Preferences survive a restart and carry over from one study to the next: the render
// parameters in preferenceKeys(), the quality choice (resolution and quality preset), the
// slice views' interpolation and the window layout (geometry, maximised view: MainWindow).
// Everything else the workstation holds belongs to the volume on screen: the camera pose,
// the clip box, the light position, the slice window/level and the crosshair. Opening a
// volume starts them from that volume's defaults, and they are never saved as preferences
// (a session file will keep them).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app_models.h"
#include "no_qt.h"
#include "voxray/io/volume.h"

namespace voxray {

// The render parameters (keys of renderParamSpecs()) that are preferences. A parameter not
// listed here is per study: reset when a volume opens, never saved. "size" is neither: the
// view decides it.
const std::vector<std::string>& preferenceKeys();
bool isPreference(const std::string& key);

// The preferences of M as key=value lines (the quality's ui- lines included), and back.
// Per-study lines (older versions saved the whole state) and bad lines are skipped, so an
// old settings file cannot bring back a clip box or a camera.
std::string preferencesText(const RenderStateModel& m);
void applyPreferences(RenderStateModel& m, const std::string& text);
// The preferences to save: M's, with the user's HU look in place of the histogram look of
// a volume whose values are not HU (value_look.h).
std::string preferencesText(const AppModels& m);

// The window/level a volume opens with, and where it came from, for display beside it.
struct InitialWindow {
  WindowLevel wl;
  std::string source;
};
// The file's window (DICOM WindowCenter/WindowWidth, first pair); else for CT 400/40; else
// (MR, unknown modality) the volume's value range.
InitialWindow initialWindow(const Volume& v);

// Makes V the document and starts every per-study state from V's defaults: the full clip
// box, the framed camera (projection and field of view are preferences and stay), the
// default light, the initial window and the crosshair at the centre. A volume whose values
// are not HU (MR, PET, unknown) gets its iso range, dvr table and mip window from its own
// histogram (valueLook), the mode staying the user's; the next CT gets the HU look back. VALUES:
// render values by key for this volume (the command line's --azimuth, --clip, ... for the volume it
// opens), applied on top; preference keys among them are skipped (they were applied when
// given). A bad value throws Error (Input), as RenderStateModel::applyValues, before the
// document changes.
void openStudy(AppModels& m, std::shared_ptr<const Volume> v, std::string name,
               const std::map<std::string, std::string>& values = {});
// A 4D series (its time points, non-empty) opened as one study with time point TIMEPOINT
// (clamped) on screen; the per-study state starts from that time point's volume.
void openStudy(AppModels& m, VolumeSeries series, std::string name,
               const std::map<std::string, std::string>& values, int timePoint);
// Puts back the volume shown before the last openStudy (the new one could not be shown)
// with the camera, clip box, light, window and crosshair it had (when openStudy opened
// the one that failed). Nothing without one.
void restorePreviousStudy(AppModels& m);

}  // namespace voxray
