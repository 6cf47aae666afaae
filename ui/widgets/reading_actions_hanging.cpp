// Hanging protocols: the rule matching the open study applied (layout, window, 3D preset),
// its series placement (a second series beside in compare's right column, more in cells), a
// session's placement checked against the study, and the rules' editor.
#include "reading_actions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QKeySequence>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "compare_view.h"
#include "gui_message.h"
#include "json_text_dialog.h"
#include "load_controller.h"
#include "main_window.h"
#include "reading_study_series.h"
#include "render_scheduler.h"
#include "series_drag.h"
#include "session_actions.h"
#include "slice_view.h"
#include "study_attributes.h"
#include "study_browser_dialog.h"
#include "view_grid.h"
#include "volume_view.h"
#include "voxray/io/error.h"
#include "window_level.h"
#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/dicom_import.h"
#endif

namespace voxray::ui {

namespace {

// Whether the compare prior is SERIES of FOLDER (a session reads its paths normalised).
bool priorIs(const AppModels& m, const std::string& folder, const std::string& series) {
  namespace fs = std::filesystem;
  return m.comparison && m.comparison->priorSeries == series &&
         fs::path(m.comparison->priorPath).lexically_normal() ==
             fs::path(folder).lexically_normal();
}
}  // namespace

#ifdef VOXRAY_HAS_DICOM
using reading_detail::openSeries;
using reading_detail::studyVolumes;
#endif

bool ReadingActions::placeSeriesOf(const HangingRule& r) {
  if (r.series.empty()) return false;
#ifdef VOXRAY_HAS_DICOM
  const auto v = models_.document.volume();
  const std::string folder = models_.source.path;
  if (!v || folder.empty() || v->study.seriesInstanceUid.empty()) return false;
  std::vector<SeriesInfo> volumes;
  try {
    volumes = studyVolumes(folder);
  } catch (const std::exception& e) {
    status("Hanging protocol: cannot list the study's series (" + QString::fromStdString(e.what()) +
           ")");
    return false;
  }
  std::vector<StudySeries> study;
  for (const auto& s : volumes) study.push_back({s.selector, s.description, s.uid});
  ReadingLayout placed{reading_.layout, placeSeries(r, study)};
  const long open = openSeries(volumes, models_);
  const std::string current = open >= 0 ? volumes[size_t(open)].selector : std::string();
  const auto shown = shownSeries(placed.layout, placed.placed);
  if (shown && *shown != current) {
    pendingPlacement_ = placed;
    LoadOptions options;
    options.series = *shown;
    window_.open(folder, options);
    return true;
  }
  hang(placed, current);
  return false;
#else
  return false;
#endif
}

void ReadingActions::hang(ReadingLayout placed, const std::string& current) {
  if (seriesInCells(placed).size() > 2 && !current.empty()) {
    // Each series in its named view: the main document's in its views, the others in cells
    // of their own (compare's columns are not needed).
    if (besideShown_) {
      besideShown_ = false;
      models_.comparison.reset();
      window_.setCompareMode(false);
    }
    setReading(placed);
    showCells(current);
    return;
  }
  const auto beside = besideSeries(placed.layout, placed.placed, current);
  placed.placed = beside ? keepShown(placed.placed, current, beside->series)
                         : keepShown(placed.placed, current);
  setReading(placed);
  if (!beside) return;
  // The second series in compare's right column: its own volume, crosshair and window,
  // linked to the study's in patient coordinates (one study: one Frame of Reference).
  besideShown_ = true;
  const std::string folder = models_.source.path;
  CompareView* c = window_.compareView();
  if (c && c->hasPrior() && priorIs(models_, folder, beside->series)) {
    window_.setCompareMode(true);
    return;
  }
  LoadOptions options;
  options.series = beside->series;
  window_.openPrior(folder, options);
}

std::vector<std::string> ReadingActions::restoreReading(const ReadingLayout& r) {
  const bool placed = std::any_of(r.placed.begin(), r.placed.end(),
                                  [](const PlacedView& p) { return !p.series.empty(); });
  const std::vector<StudySeries> study = placed ? studySeries() : std::vector<StudySeries>{};
  // No listing (not a DICOM folder, or unreadable): the placement as saved.
  const ReadingLayout checked = study.empty() ? r : checkPlacement(r, study);
  std::vector<std::string> notes;
  for (size_t i = 0; i < r.placed.size(); ++i)
    if (!r.placed[i].series.empty() && checked.placed[i].series.empty()) {
      notes.push_back(gridViewName(checked.placed[i].view) + ": " + checked.placed[i].note);
      // The session's second column was that series: it does not open.
      if (priorIs(models_, models_.source.path, r.placed[i].series)) models_.comparison.reset();
    }
  const auto cells = seriesInCells(checked);
  besideShown_ = cells.size() > 1 && priorIs(models_, models_.source.path, cells[1]);
  setReading(checked);
  if (cells.size() > 2) showCells(openSeriesSelector());  // each series in its cell again
  return notes;
}

QString ReadingActions::applyHangingProtocol() {
  const auto v = models_.document.volume();
  if (!v) return {};
  const HangingRule* r = matchRule(protocols_, studyAttributes(*v, models_.source.path));
  if (!r) return {};
  if (r->layout) setReading(ReadingLayout{*r->layout, {}});
  pendingRule_.reset();
  if (placeSeriesOf(*r)) {  // its series opens; the rest is applied once it is shown
    pendingRule_ = *r;
    return QString::fromStdString(r->name);
  }
  return applyLook(r);
}

QString ReadingActions::applyLook(const HangingRule* rule) {
  const HangingRule* r = rule;
  if (!r->window.empty())
    for (const auto& p : windowLevelPresets())
      if (p.name == r->window) models_.windowLevel.reset(p.wl, "hanging protocol: " + r->name);
  if (!r->preset.empty()) {
    try {
      models_.render.applyPreset(r->preset);
    } catch (const std::exception& e) {  // parse checked the name: a bug if it happens
      emit failed("Hanging protocol", QString::fromStdString(e.what()));
    }
  }
  const QString name = QString::fromStdString(r->name);
  const QString notes = emptyViewsText();
  status("Hanging protocol: " + name + (notes.isEmpty() ? "" : "  ·  " + notes));
  emit protocolApplied(name);
  return name;
}

void ReadingActions::setProtocolsJson(const std::string& json) {
  HangingProtocols p = parseHangingProtocols(json);
  saveHangingProtocols(hangingProtocolsPath().toStdString(), p);
  protocols_ = std::move(p);
}

void ReadingActions::showHangingProtocolEditor() {
  JsonTextDialog d(&window_, "Hanging protocols",
                   "Rules picking the layout, window and 3D preset when a study opens; the "
                   "first whose every match field fits wins. A pattern is a case-insensitive "
                   "substring, or /a regex/. Layouts: 1x1, 1x2, 2x2, 1+3, mpr+3d, 3d. \"series\": "
                   "{\"axial\": \"T2\", \"3d\": 2} puts the study's series in views by "
                   "description or by place (1, 2, …); two series show side by side, three or "
                   "four each in its own cell, linked in patient coordinates.",
                   QString::fromStdString(hangingProtocolsJson(protocols_)),
                   QString::fromStdString(defaultHangingProtocolsJson()),
                   [this](const std::string& json) { setProtocolsJson(json); });
  d.exec();
}

}  // namespace voxray::ui
