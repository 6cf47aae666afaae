#include "help_dialogs.h"

#include <map>
#include <string>
#include <string_view>

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

#include "voxray/io/sample_volume.h"

namespace voxray {
// resources/sample/LICENSE-head-phantom-ct, embedded (resources/CMakeLists.txt).
const std::map<std::string, std::string_view>& embeddedSampleCtLicence();
}  // namespace voxray

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
    {"Slice view: wheel, arrow keys", "next slice (pages: Reading → Page forward / back)"},
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

QString sampleDataLicence() {
  const auto& files = embeddedSampleCtLicence();
  auto it = files.find("LICENSE-head-phantom-ct");
  return it == files.end() ? QString() : QString::fromUtf8(it->second.data(), it->second.size());
}

QString aboutHtml(const QString& device) {
  // Every library the workstation links, what for, and its licence (Debian's builds).
  struct Library {
    const char* name;
    const char* use;
    const char* licence;
  };
  static const Library libraries[] = {
      {"Qt", "the workstation's windows", "LGPL-3.0"},
      {"OpenCL headers", "the raycaster", "Apache-2.0"},
      {"OpenCL ICD loader (ocl-icd)", "the raycaster", "BSD-2-Clause"},
      {"PoCL", "OpenCL on CPUs", "MIT"},
      {"GLM", "geometry", "MIT"},
      {"nlohmann/json", "sessions, presets, DICOMweb", "MIT"},
      {"zlib", "the sample CT, compressed files", "Zlib"},
      {"OpenImageIO", "image export and import", "Apache-2.0"},
      {"FFmpeg (libavcodec, libavformat, libavutil, libswscale)", "MP4 export",
       "LGPL-2.1-or-later; as Debian builds it, with GPL parts: GPL-2.0-or-later"},
      {"x264", "H.264 encoding of MP4 movies", "GPL-2.0-or-later"},
#ifdef VOXRAY_HAS_DICOM
      {"DCMTK", "DICOM import, DIMSE PACS client", "BSD-3-Clause"},
      {"OpenJPEG", "JPEG 2000 DICOM images", "BSD-2-Clause"},
      {"libcurl", "DICOMweb PACS client", "curl licence (MIT-style)"},
#endif
#ifdef VOXRAY_HAS_FORMATS
      {"NIfTI C library (nifti2, znz)", "NIfTI import", "public domain"},
      {"Teem", "NRRD import",
       "LGPL-2.1-or-later with a static-linking exception (Simple Library Usage License)"},
      {"MetaIO (from ITK)", "MetaImage import", "Apache-2.0"},
#endif
  };
  QString rows;
  for (const Library& l : libraries)
    rows += QString("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
                .arg(QString(l.name).toHtmlEscaped(), QString(l.use).toHtmlEscaped(),
                     QString(l.licence).toHtmlEscaped());
  return QString(
             "<h3>Voxray %1</h3>"
             "<p>CT and MR volume viewer with an OpenCL raycaster.</p>"
             "<p><b>OpenCL device:</b> %2</p>"
             "<p><b>Libraries and their licences</b> (Qt %3; voxray-cli also uses CLI11, "
             "BSD-3-Clause):</p><table cellspacing=2>%4</table>"
             "<p><b>Data:</b> %5 It may be redistributed, changed or not, in source or binary "
             "form, provided that its copyright notice, the licence's two conditions and its "
             "disclaimer go with it; it comes as is, without any warranty (Show Details… "
             "gives the licence in full). The built-in head phantom is synthetic (made by "
             "Voxray). Test scans: Stanford volume archive (CThead, MRbrain), InVesalius "
             "examples (GPL-2), visvis stent (BSD), DICOM sets from dcm_qa (BSD-2) and pydicom "
             "(MIT).</p>")
      .arg(QApplication::applicationVersion().toHtmlEscaped(), device.toHtmlEscaped(),
           QString(qVersion()), rows,
           QString::fromStdString(sampleCtAttribution()).toHtmlEscaped());
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
  // The sample CT's BSD-2-Clause licence asks binaries to reproduce it: here, in full.
  box.setDetailedText(sampleDataLicence());
  box.exec();
}

}  // namespace voxray::ui
