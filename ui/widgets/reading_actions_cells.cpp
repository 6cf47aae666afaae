// More than two series placed: each other series in a cell of its own (series_cells.h), an
// axial slice view or, in the 3D view's place, a 3D view with its own render thread.
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

VolumeView* ReadingActions::cell3dView() const { return cell3d_.data(); }

SliceView* ReadingActions::cellView(GridView view) const {
  auto it = cellViews_.find(view);
  return it == cellViews_.end() ? nullptr : it->second.data();
}

void ReadingActions::closeCell(GridView view) {
  if (auto it = cellViews_.find(view); it != cellViews_.end()) {
    if (it->second) {
      QWidget* box = it->second->parentWidget();  // the view and its name
      window_.grid().setCellView(view, nullptr);
      delete box;
    }
    cellViews_.erase(it);
  }
  if (view == GridView::Volume3d && cell3dScheduler_) {
    if (cell3d_) {
      QWidget* box = cell3d_->parentWidget();
      window_.grid().setCellView(view, nullptr);
      delete box;
    }
    cell3dScheduler_.reset();  // after its view
  }
  if (auto it = cellLoaders_.find(view); it != cellLoaders_.end()) {
    delete it->second.data();  // cancels a load under way and waits for it
    cellLoaders_.erase(it);
  }
  std::vector<PlacedView> rest;
  for (const auto& c : cells_->cells())
    if (c->placed.view != view) rest.push_back(c->placed);
  cells_->setCells(rest);
}

void ReadingActions::showCells(const std::string& current) {
  const std::vector<PlacedView> wanted = cellsToOpen(reading_, current);
  for (GridView v : cells_->leaving(wanted)) closeCell(v);
  const std::string folder = models_.source.path;
  cellsFolder_ = folder;
  for (GridView v : cells_->setCells(wanted)) {
    SeriesCell& c = *cells_->cell(v);
    // An axial view of the cell's series, as compare's columns show theirs: the cells read
    // side by side, one patient z in each.
    const std::string series = c.placed.series;
    const QString name =
        QString::fromStdString(c.placed.description.empty() ? series : c.placed.description);
    // The series' name above its view (as compare's columns have): which cell is which.
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(new QLabel(name));
    QWidget* view = nullptr;
    if (v == GridView::Volume3d) {
      // The 3D view's place: the series in 3D, through a render thread (and device copy) of
      // its own on the window's device, as compare's prior column.
      cell3dScheduler_ = std::make_unique<RenderScheduler>(c.render, c.document,
                                                           QString::fromStdString(models_.device));
      cell3d_ = new VolumeView(c.render, c.document, c.crosshair, *cell3dScheduler_);
      view = cell3d_;
    } else {
      // An axial view of the cell's series, as compare's columns show theirs: the cells read
      // side by side, one patient z in each.
      auto* slice =
          new SliceView(Orientation::Axial, c.document, c.crosshair, c.windowLevel, c.render);
      cellViews_[v] = slice;
      view = slice;
    }
    view->setObjectName(QString::fromStdString("seriesCell-" + gridViewName(v)));
    layout->addWidget(view, 1);
    window_.grid().setCellView(v, box);
    if (SeriesDropFilter* drops = window_.seriesDrops()) drops->watch(view);
    auto* loader = new LoadController(&window_);
    cellLoaders_[v] = loader;
    connect(loader, &LoadController::loaded, this,
            [this, v, series](VolumeSeries s, const QString& n, const QString&) {
              // Its cell may have gone or changed series while it loaded.
              if (SeriesCell* now = cells_->cell(v); now && now->placed.series == series)
                cells_->setVolume(v, std::move(s), n.toStdString());
            });
    connect(loader, &LoadController::failed, this, [this, v, name](const QString& m) {
      emit failed(
          "Cannot open " + name + " in the " + QString::fromStdString(gridViewName(v)) + " view",
          m);
    });
    LoadOptions options;
    options.series = series;
    loader->load(folder, options, name);
  }
}

}  // namespace voxray::ui
