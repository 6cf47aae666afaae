#pragma once
// The dialogs' one std::string -> QString conversion (UTF-8), shared rather than copied into
// each dialog's file, so that a unity build can merge those files.
#include <QString>
#include <string>

namespace voxray::ui {

inline QString toQString(const std::string& s) { return QString::fromStdString(s); }

}  // namespace voxray::ui
