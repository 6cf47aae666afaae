#include "help_dialogs.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

#include "voxray/io/sample_volume.h"

namespace voxray::ui {

namespace {

// The views handle these keys and buttons themselves (volume_view.cpp, slice_view.cpp);
// they have no QAction to read them from.
constexpr const char* kViewControls[][2] = {
    {"3D view: left drag", "rotate; on a clip box face: move that face; on the light: move it"},
    {"3D view: right drag / wheel", "zoom"},
    {"3D view: middle or Shift+left drag", "pan"},
    {"3D view: arrow keys", "rotate by a step"},
    {"3D view: R", "reset the camera"},
    {"Slice view: left click or drag", "move the crosshair; on a clip edge: move that edge"},
    {"Slice view: drag a round handle on a crosshair line",
     "turn the other two planes about this view's normal (oblique MPR)"},
    {"Slice view: right drag", "window (left-right) and level (up-down)"},
    {"Slice view: middle drag", "pan"},
    {"Slice view: wheel, arrow keys, Page Up/Down", "next slice (Page: 10 slices)"},
    {"Slice view: Ctrl+wheel", "zoom"},
    {"Any view: double click", "maximise or restore it"},
    {"3D view: Ctrl+click (iso, dvr)",
     "pick a surface point (dvr: where opacity reaches 50 %); two make a distance"},
    {"Slice view: left drag with a measuring tool", "draw it; on a handle: move that point"},
    {"Slice view: Del / Esc", "delete the selected measurement / back to the pointer"},
};

void addMenuRows(const QMenu& menu, const QString& path, QString& rows) {
  for (QAction* a : menu.actions()) {
    QString name = path + " → " + a->text().remove('&').remove(QChar(0x2026)).trimmed();
    if (a->menu()) {
      addMenuRows(*a->menu(), name, rows);
      continue;
    }
    if (a->isSeparator() || a->shortcut().isEmpty()) continue;
    rows += QString("<tr><td><b>%1</b></td><td>%2</td></tr>")
                .arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(),
                     name.toHtmlEscaped());
  }
}

}  // namespace

QString shortcutsHtml(const QMenuBar& menus) {
  QString rows;
  for (QAction* a : menus.actions())
    if (a->menu()) addMenuRows(*a->menu(), a->text().remove('&'), rows);
  for (const auto& c : kViewControls)
    rows += QString("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(c[0], c[1]);
  return "<table cellspacing=4>" + rows + "</table>";
}

QString aboutHtml(const QString& device) {
  return QString(
             "<h3>Voxray %1</h3>"
             "<p>CT and MR volume viewer with an OpenCL raycaster.</p>"
             "<p><b>OpenCL device:</b> %2</p>"
             "<p><b>Libraries and their licences:</b> Qt %3 (LGPL-3.0), DCMTK (BSD-3-Clause), "
             "OpenJPEG (BSD-2-Clause), OpenImageIO (Apache-2.0), GLM (MIT), CLI11 "
             "(BSD-3-Clause), OpenCL headers (Apache-2.0), zlib (Zlib); on CPUs PoCL (MIT).</p>"
             "<p><b>Data:</b> %4 Its licence: resources/sample/LICENSE-head-phantom-ct. "
             "The built-in head phantom is synthetic (made by Voxray). Test "
             "scans: Stanford volume archive (CThead, MRbrain), InVesalius examples (GPL-2), "
             "visvis stent (BSD), DICOM sets from dcm_qa (BSD-2) and pydicom (MIT).</p>")
      .arg(QApplication::applicationVersion().toHtmlEscaped(), device.toHtmlEscaped(),
           QString(qVersion()), QString::fromStdString(sampleCtAttribution()).toHtmlEscaped());
}

void showShortcuts(QWidget* parent, const QMenuBar& menus) {
  QMessageBox box(QMessageBox::NoIcon, "Keyboard shortcuts", shortcutsHtml(menus),
                  QMessageBox::Close, parent);
  box.setTextFormat(Qt::RichText);
  box.exec();
}

void showAbout(QWidget* parent, const QString& device) {
  QMessageBox box(QMessageBox::NoIcon, "About Voxray", aboutHtml(device), QMessageBox::Close,
                  parent);
  box.setTextFormat(Qt::RichText);
  box.exec();
}

}  // namespace voxray::ui
