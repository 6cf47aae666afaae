#pragma once
// The workstation's state as a session file (voxray/engine/session.h) and back: what
// File → Save session writes and Open session restores, Qt-free so that a test can save
// the models' state and compare voxray-cli's render of it with the 3D view's frame.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app_models.h"
#include "no_qt.h"
#include "session.h"

namespace voxray {

// M's state: its input (M.source), every render parameter with "size" set to VIEWSIZE (the
// 3D view's size in pixels), the quality choice, the slice window/level, crosshair and
// interpolation, the 3D view's overlays, LAYOUT (a sessionLayouts() name) and the
// measurements.
// READING: the reading layout and the series a hanging protocol placed (none: not saved).
// The fusion overlay is saved when it was read from a file (FusionModel::sourcePath).
Session sessionFromModels(const AppModels& m, const glm::ivec2& viewSize, const std::string& layout,
                          const std::optional<ReadingLayout>& reading = std::nullopt);

// The overlay's settings as a session keeps them (F's input from its source), and back: the
// saved window, map, opacity and on/off onto FUSION's overlay just opened from F.input.
// Returns what could not be applied: a window saved in another unit than the overlay's now
// (e.g. SUVbw, and the overlay lost its weight) keeps the overlay's first window, said.
Session::Fusion sessionFusion(const FusionModel& fusion);
std::vector<std::string> applySessionFusion(FusionModel& fusion, const Session::Fusion& f);

// Sets everything S holds on the study just opened (openStudy) from S.input: render
// parameters (the view keeps deciding the size), quality, window/level, crosshair, slice
// interpolation, the 3D view's overlays, measurements, the segmentation, the input. The
// layout is the window's to apply. Returns the problems to tell the user: parts it could not
// apply (a segmentation made on another grid than the volume's is left out, not resampled).
std::vector<std::string> applySession(AppModels& m, const Session& s);
// openStudy of V, then applySession.
std::vector<std::string> openSession(AppModels& m, std::shared_ptr<const Volume> v,
                                     std::string name, const Session& s);

// Whether PATH names a session file (".json") rather than a volume: the recent-files list
// holds both.
bool isSessionPath(const std::string& path);

}  // namespace voxray
