#pragma once
// Help → Keyboard shortcuts and Help → About.
#include <QString>

class QMenuBar;
class QWidget;

namespace voxray::ui {

// The shortcuts of every menu action (read from MENUS, so a new action lists itself) and the
// mouse and keys of the views, as an HTML table.
QString shortcutsHtml(const QMenuBar& menus);
// Version, OpenCL device, every linked library with its licence, and where the data came
// from with its licence.
QString aboutHtml(const QString& device);
// The sample CT's licence in full (resources/sample/LICENSE-head-phantom-ct, embedded): the
// About box's details.
QString sampleDataLicence();

void showShortcuts(QWidget* parent, const QMenuBar& menus);
void showAbout(QWidget* parent, const QString& device);

}  // namespace voxray::ui
