#pragma once
// Help → Keyboard shortcuts and Help → About.
#include <QString>

class QMenuBar;
class QWidget;

namespace voxray::ui {

// The shortcuts of every menu action (read from MENUS, so a new action lists itself) and the
// mouse and keys of the views, as an HTML table.
QString shortcutsHtml(const QMenuBar& menus);
// Version, OpenCL device, licences of Voxray's libraries and where the data came from.
QString aboutHtml(const QString& device);

void showShortcuts(QWidget* parent, const QMenuBar& menus);
void showAbout(QWidget* parent, const QString& device);

}  // namespace voxray::ui
