// The open study's series: listed in the study's order, Show series in this view, a series
// dropped from the study browser, next/previous series and next/previous study.
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

#ifdef VOXRAY_HAS_DICOM
namespace reading_detail {

std::vector<SeriesInfo> studyVolumes(const std::string& folder) {
  std::vector<SeriesInfo> volumes;
  for (const auto& s : listDicomSeries(folder).series)
    if (s.isVolume) volumes.push_back(s);
  std::stable_sort(volumes.begin(), volumes.end(), [](const auto& a, const auto& b) {
    return std::pair(a.number, a.part) < std::pair(b.number, b.part);
  });
  return volumes;
}

long openSeries(const std::vector<SeriesInfo>& volumes, const AppModels& m) {
  const auto v = m.document.volume();
  const auto flag = m.source.flags.find("series");
  for (int pass = 0; pass < 2; ++pass)  // the selector it was opened with, else its UID
    for (size_t i = 0; i < volumes.size(); ++i) {
      const bool bySelector = pass == 0 && flag != m.source.flags.end() && !flag->second.empty();
      if (bySelector ? volumes[i].selector == flag->second
                     : pass == 1 && v && volumes[i].uid == v->study.seriesInstanceUid)
        return long(i);
    }
  return -1;
}

}  // namespace reading_detail

using reading_detail::openSeries;
using reading_detail::studyVolumes;
#endif

std::string ReadingActions::openSeriesSelector() const {
#ifdef VOXRAY_HAS_DICOM
  const auto v = models_.document.volume();
  if (!v || models_.source.path.empty() || v->study.seriesInstanceUid.empty()) return {};
  try {
    const auto volumes = studyVolumes(models_.source.path);
    const long open = openSeries(volumes, models_);
    return open >= 0 ? volumes[size_t(open)].selector : std::string();
  } catch (const std::exception&) {
    return {};
  }
#else
  return {};
#endif
}

std::vector<StudySeries> ReadingActions::studySeries() const {
  std::vector<StudySeries> study;
#ifdef VOXRAY_HAS_DICOM
  const auto v = models_.document.volume();
  if (!v || models_.source.path.empty() || v->study.seriesInstanceUid.empty()) return study;
  try {
    for (const auto& s : studyVolumes(models_.source.path))
      study.push_back({s.selector, s.description, s.uid});
  } catch (const std::exception&) {  // an unreadable folder: no series to offer
  }
#endif
  return study;
}

void ReadingActions::showSeriesInView(GridView view, const StudySeries& s) {
  const std::string current = openSeriesSelector();
  ReadingLayout r = reading_;
  // Views holding a third series show the open volume again (two series at once).
  r.placed.erase(std::remove_if(r.placed.begin(), r.placed.end(),
                                [&](const PlacedView& p) {
                                  return p.view != view && p.series != current &&
                                         p.series != s.selector;
                                }),
                 r.placed.end());
  r = placeInView(r, view, s);
  // The other cells show the open series (placed, so the session keeps them).
  for (const LayoutCell& c : layoutCells(r.layout))
    if (std::none_of(r.placed.begin(), r.placed.end(),
                     [&](const PlacedView& p) { return p.view == c.view; })) {
      const auto study = studySeries();
      auto it = std::find_if(study.begin(), study.end(),
                             [&](const StudySeries& x) { return x.selector == current; });
      if (it != study.end()) r = placeInView(r, c.view, *it);
    }
  hang(r, current);
}

void ReadingActions::dropSeries(QWidget* target, const SeriesDrag& d) {
  // A series of the open study (by its UID; the browser's folder is the database's view of
  // it) opens from the study's folder as the study lists it, so that Show series in this view
  // and sessions name it the same way; another study's from the browser's folder.
  std::optional<StudySeries> own;
  for (const StudySeries& s : studySeries())
    if (s.uid == d.uid.toStdString()) own = s;
  const std::string folder = own ? models_.source.path : d.folder.toStdString();
  LoadOptions options;
  options.series = own ? own->selector : d.series.toStdString();
  const QString name = d.description.isEmpty() ? d.series : d.description;
  // Compare's columns: the left one is the main document, the right one compare's own; the
  // other column stays as it is.
  if (CompareView* c = window_.compareView(); c && c->isVisible()) {
    if (target == &c->movingView() || target == &c->moving3dView()) {
      status(name + " opens in the right column");
      window_.openPrior(folder, options);
    } else {
      status(name + " opens in the left column");
      window_.open(folder, options);
    }
    return;
  }
  // A series cell's view: the series goes in that cell (a series of the open study; another
  // study's opens beside, as on the grid's other cells). Later: the drop's view may close.
  std::map<GridView, QWidget*> cellWidgets;
  for (const auto& [cell, w] : cellViews_) cellWidgets[cell] = w.data();
  if (cell3d_) cellWidgets[GridView::Volume3d] = cell3d_.data();
  for (const auto& [cell, w] : cellWidgets)
    if (w && w == target) {
      if (!own) {
        status(name + " opens beside");
        window_.openPrior(folder, options);
        return;
      }
      status(name + " opens in the " + QString::fromStdString(gridViewName(cell)) + " view");
      // A copy: a structured binding cannot be captured in C++17.
      QTimer::singleShot(0, this, [this, at = cell, s = *own] {
        hang(placeInView(reading_, at, s), openSeriesSelector());
      });
      return;
    }
  std::optional<GridView> view;
  if (target == &window_.volumeView()) view = GridView::Volume3d;
  for (int i = 0; i < 3; ++i)
    if (target == &window_.sliceView(i)) view = GridView(i + 1);
  if (!view) return;
  // The layout's first cell is the main document's (the left column once two series show).
  const auto cells = visibleCells(reading_);
  if (!cells.empty() && cells.front().view == *view) {
    status(name + " opens as the main series");
    window_.open(folder, options);
  } else if (own) {
    showSeriesInView(*view, *own);  // as Reading → Show series in this view does
  } else {
    status(name + " opens beside");  // another study's series: in compare's right column
    window_.openPrior(folder, options);
  }
}

void ReadingActions::fillSeriesMenu(QMenu* menu) {
  menu->clear();
  const auto study = studySeries();
  if (study.empty()) {
    menu->addAction("(the open volume is no DICOM series of a study)")->setEnabled(false);
    return;
  }
  for (const StudySeries& s : study) {
    QAction* a =
        menu->addAction(QString::fromStdString(s.description.empty() ? s.selector : s.description),
                        this, [this, s] { showSeriesInView(focusedGridView(), s); });
    a->setObjectName(QString::fromStdString("readingShowSeries-" + s.selector));
  }
}

void ReadingActions::stepSeries(int step) {
#ifdef VOXRAY_HAS_DICOM
  const auto v = models_.document.volume();
  const std::string folder = models_.source.path;
  if (!v || folder.empty() || v->study.seriesInstanceUid.empty()) {
    status("Next series: the open volume is not a DICOM series");
    return;
  }
  DicomListing listing;
  try {
    listing = listDicomSeries(folder);
  } catch (const std::exception& e) {
    emit failed("Cannot list the study's series", QString::fromStdString(e.what()));
    return;
  }
  std::vector<SeriesInfo> volumes;
  for (const auto& s : listing.series)
    if (s.isVolume) volumes.push_back(s);
  std::stable_sort(volumes.begin(), volumes.end(), [](const auto& a, const auto& b) {
    return std::pair(a.number, a.part) < std::pair(b.number, b.part);
  });
  const auto flag = models_.source.flags.find("series");
  auto current = std::find_if(volumes.begin(), volumes.end(), [&](const SeriesInfo& s) {
    return flag != models_.source.flags.end() && !flag->second.empty()
               ? s.selector == flag->second
               : s.uid == v->study.seriesInstanceUid;
  });
  if (current == volumes.end())
    current = std::find_if(volumes.begin(), volumes.end(), [&](const SeriesInfo& s) {
      return s.uid == v->study.seriesInstanceUid;
    });
  const long at = current == volumes.end() ? -1 : long(current - volumes.begin());
  const long next = at + step;
  if (at < 0 || next < 0 || next >= long(volumes.size())) {
    status(step > 0 ? "No next series in this study's folder"
                    : "No previous series in this study's folder");
    return;
  }
  LoadOptions options;
  options.series = volumes[size_t(next)].selector;
  window_.open(folder, options);
#else
  status("This build reads no DICOM series");
#endif
}

void ReadingActions::stepStudy(int step) {
#ifdef VOXRAY_HAS_STUDYDB
  StudyBrowserDialog* b = window_.findChild<StudyBrowserDialog*>();
  const auto v = models_.document.volume();
  if (!b || !b->tree() || b->tree()->topLevelItemCount() == 0) {
    status("Next study follows the study browser's list: open it (Ctrl+B) and search first");
    return;
  }
  // The browser's studies in the order shown: each patient's, patient by patient.
  std::vector<QTreeWidgetItem*> studies;
  for (int i = 0; i < b->tree()->topLevelItemCount(); ++i) {
    QTreeWidgetItem* patient = b->tree()->topLevelItem(i);
    for (int j = 0; j < patient->childCount(); ++j) studies.push_back(patient->child(j));
  }
  const QString uid = v ? QString::fromStdString(v->study.studyInstanceUid) : QString();
  long at = -1;
  for (size_t i = 0; i < studies.size(); ++i)
    if (!uid.isEmpty() && studies[i]->data(0, Qt::UserRole).toString() == uid) at = long(i);
  // Not in the list: next starts at its first study, previous at its last.
  const long next = at < 0 ? (step > 0 ? 0 : long(studies.size()) - 1) : at + step;
  if (next < 0 || next >= long(studies.size())) {
    status(step > 0 ? "The last study of the browser's list is open"
                    : "The first study of the browser's list is open");
    return;
  }
  b->tree()->setCurrentItem(studies[size_t(next)]);
  b->openItem(studies[size_t(next)]);
#else
  status("This build has no study database");
#endif
}

}  // namespace voxray::ui
