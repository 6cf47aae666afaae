#pragma once
// View → Theme. Qt 6.4 (Debian 12) has no QStyleHints::colorScheme, so "System" follows the
// desktop through the palette the platform theme gives at start (QT_QPA_PLATFORMTHEME:
// gtk3 gives Adwaita-dark's palette, qt5ct/qt6ct theirs); Light and Dark override it with
// Fusion's palettes. The choice is saved with the window layout.
#include <QString>
#include <QStringList>

namespace voxray::ui {

// "System", "Light", "Dark": the menu's entries and the saved values.
const QStringList& themeNames();
// Applies NAME to the application (an unknown name: System). The first call remembers the
// platform's palette and style, so that System can go back to them.
void applyTheme(const QString& name);

}  // namespace voxray::ui
