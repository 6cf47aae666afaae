#pragma once
// A session file: what the workstation shows, saved as one versioned JSON file that the
// workstation opens again and `voxray-cli render --session` renders. Qt-free and here (not
// in ui/) so that voxray-cli, which links no Qt, reads the same schema.
//
// Render parameters are written and read through renderParamSpecs() (the one declaration),
// the input's raw layout and series through inputFlagSpecs(): a parameter added there is
// saved without a change here. Measurements are kept as JSON text, untouched.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "layout_model.h"
#include "view_overlays.h"
#include "voxray/engine/plane_sampler.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/segmentation.h"
#include "window_level.h"

namespace voxray {

// The schema version this build writes, and the newest it reads.
inline constexpr int kSessionVersion = 1;

struct SessionInput {
  std::string path;                          // absolute once read; empty: the embedded head phantom
  std::map<std::string, std::string> flags;  // keys of inputFlagSpecs(): raw layout, series
  bool operator==(const SessionInput&) const = default;
};

// The slice views' layout names, in the workstation's grid order ("grid": none maximised).
const std::vector<std::string>& sessionLayouts();

// One slice view's plane (axial, coronal, sagittal): turned about the crosshair, and its slab.
struct SessionView {
  glm::dmat3 rotation{1.0};  // LPS, a proper rotation; the identity: the acquisition plane
  Slab slab;                 // thickness 0: a thin slice
};

struct Session {
  SessionInput input;
  // Every render parameter; "size" is the 3D view's size in pixels when it was saved.
  RenderParams render;
  std::string qualityPreset = "balanced";  // resources/quality name; empty: custom
  glm::ivec2 resolution{0, 0};             // the resolution choice; {0, 0}: the view's size
  WindowLevel window;                      // the slice views' window/level (HU for CT)
  glm::ivec3 crosshair{0};  // the slice views' voxel (i, j, k): the three slice positions
  // While a view is turned the crosshair moves off voxel centres: its continuous voxel
  // position (none: the crosshair voxel). Optional in the file, as are the views.
  std::optional<glm::dvec3> centre;
  std::array<SessionView, 3> views{};  // axial, coronal, sagittal
  Interp sliceInterp = Interp::Linear;
  std::string layout = "grid";  // one of sessionLayouts()
  // The 3D view's overlays; optional in the file (older sessions: the defaults).
  ViewOverlays overlays;
  // The transfer function the editor shaped, when the render table is still its own: its
  // colour and opacity lists and curve (the table alone loses them). Optional in the file.
  std::optional<VolumeProperty> transferFunction;
  std::string measurements = "[]";  // a JSON array owned by the measuring tools, kept as read
  // Text and arrow annotations (annotation_model.h), a JSON array kept as read; optional in the
  // file (older sessions have none).
  std::string annotations = "[]";
  // The segment editor's segmentation (issue 34); optional in the file. Its grid is checked
  // against the volume when the session is applied (session_state.h).
  std::optional<Segmentation> segmentation;
  // A 4D series: the time point on screen (0-based) and the play rate (frames per second).
  // Optional in the file ("time"); written only for a series of more than one time point.
  struct Time {
    int point = 0;
    double fps = 10.0;
  };
  std::optional<Time> time;
  // Compare (issue 36): the prior beside the study and, once aligned, the rigid transform
  // of its patient coordinates onto the study's (LPS mm). Optional in the file ("comparison").
  struct Comparison {
    std::string priorPath;                    // absolute
    std::optional<glm::dmat4> movingToFixed;  // none: linked by a shared Frame of Reference only
    // A 4D prior's own time point (time_follow.h: shown while it does not follow the study's).
    int priorTimePoint = 0;
    // The prior's series in PRIORPATH (LoadOptions::series; empty: the default choice): a
    // layout's second series of the study is its prior. Optional in the file ("series").
    std::string priorSeries{};
    // The "Link 3D look" box and the prior's 3D camera (issue 36). Optional in the file
    // ("link-look", "prior-camera"; older sessions: linked, the camera the link gives).
    bool linkLook = true;
    std::optional<CameraParams> priorCamera{};
  };
  std::optional<Comparison> comparison;
  // The reading layout (issue 37: 1x1 ... 3d, Ctrl+1..6) and what a hanging protocol placed in
  // which view. Optional in the file ("reading"; older sessions: the window's layout stays).
  std::optional<ReadingLayout> reading;
  // The fusion overlay (issue 36): its file, how it opens and how it is shown. Optional in the
  // file ("fusion"; older sessions: none).
  struct Fusion {
    SessionInput input;  // path absolute once read; flags as the study's
    std::string colormap = "hot-iron";
    double lo = 0.0, hi = 1.0;  // in the overlay's display unit (SUVbw for a PET with SUV)
    std::string unit;           // that unit when saved ("SUVbw", "Bq/ml", ...), for the reader
    double opacity = 0.5;
    bool on = true;
    // A 4D overlay's own time point (time_follow.h: shown while it does not follow the study's).
    int timePoint = 0;
    bool operator==(const Fusion&) const = default;
  };
  std::optional<Fusion> fusion;
};

struct SessionRead {
  Session session;
  // Fields this version does not know (ignored) and render parameters the file lacks (left
  // at their defaults), each as one line naming the field.
  std::vector<std::string> warnings;
  // Non-empty when the input is at none of these paths (the session's folder first, then
  // where it was saved from): the data moved. session.input.path is the first of them.
  std::vector<std::string> missingInput;
  // Non-empty when the fusion overlay's file is at none of these paths: the session opens
  // without the overlay, and says so (session.fusion keeps its settings).
  std::vector<std::string> missingFusion;
};

// S as JSON. SESSIONPATH: where it will be written; the input is stored relative to its
// folder, with the absolute path beside it as a fallback.
std::string sessionToJson(const Session& s, const std::string& sessionPath);
// Throws Error (Input) naming SESSIONPATH and the field: not JSON, a missing required field,
// a wrong type or bad value, a newer schema version.
SessionRead sessionFromJson(const std::string& json, const std::string& sessionPath);

SessionRead readSessionFile(const std::string& path);  // throws Error (Input)
// Writes atomically. An existing file is replaced only with REPLACE (the user said yes, or
// --force); otherwise Error (Output) says so. Throws Error (Output) when it cannot write.
void writeSessionFile(const std::string& path, const Session& s, bool replace);

// What to tell a user whose session data moved (SessionRead::missingInput): which paths
// were tried and what to do. FIX: the way to give the new location in this front end.
std::string movedDataMessage(const std::string& sessionPath, const std::vector<std::string>& tried,
                             const std::string& fix);

}  // namespace voxray
