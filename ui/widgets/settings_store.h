#pragma once
// What persists between sessions (QSettings): the user's preferences (study_state.h says
// which; never the camera, clip box, light or window/level of a study) as the engine's
// key=value text, recent files and the raw layout last used for each file (dims, type,
// byte order, header, spacing, rescale, slice range and axes code).
#include <optional>
#include <string>
#include <vector>

#include <QSettings>

#include "app_models.h"
#include "voxray/io/raw_import.h"

namespace voxray::ui {

void saveModelSettings(QSettings& s, const AppModels& m);
void loadModelSettings(QSettings& s, AppModels& m);

std::vector<std::string> loadRecent(QSettings& s);
void saveRecent(QSettings& s, const std::vector<std::string>& list);

void saveRawLayoutFor(QSettings& s, const std::string& path, const RawLayout& l);
std::optional<RawLayout> loadRawLayoutFor(QSettings& s, const std::string& path);

}  // namespace voxray::ui
