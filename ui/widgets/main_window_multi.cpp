// MainWindow's part of issue 36's multi-volume work: the fusion overlay (File → Open overlay
// volume…, the Fusion dock, the slice views' overlay, the 3D view's fused dvr) and compare
// (File → Compare with prior…, the two columns in place of the four views).
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QSplitter>
#include <QStatusBar>

#include "compare_view.h"
#include "coupling.h"
#include "fusion_panel.h"
#include "gui_message.h"
#include "load_controller.h"
#include "main_window.h"
#include "series_drag.h"
#include "slice_view.h"
#include "volume_view.h"

namespace voxray::ui {

void MainWindow::wireFusion() {
  for (SliceView* s : slices_) s->setFusion(&models_.fusion);
  fusionPanel_ = new FusionPanel(models_.fusion);
  fusionDock_ = new QDockWidget("Fusion");
  fusionDock_->setObjectName("fusionDock");
  fusionDock_->setWidget(fusionPanel_);
  addDockWidget(Qt::RightDockWidgetArea, fusionDock_);
  tabifyDockWidget(measureDock_, fusionDock_);
  measureDock_->raise();
  overlayLoader_ = new OverlayLoader(models_, this);
  connect(fusionPanel_, &FusionPanel::openRequested, this, [this] {
    const std::string input = askVolumeInput(this, "Open overlay volume");
    if (!input.empty()) openOverlay(input);
  });
  connect(overlayLoader_, &OverlayLoader::opened, this,
          [this](const QString& name, const QStringList& warnings) {
            fusionDock_->show();
            fusionDock_->raise();
            // No shared Frame of Reference: shown anyway, and said.
            statusBar()->showMessage(
                "Overlay " + name + (warnings.isEmpty() ? "" : ": " + warnings.join("  ·  ")),
                30000);
          });
  connect(overlayLoader_, &OverlayLoader::failed, this,
          [this](const QString& m) { showError("Cannot open the overlay", m); });
  // Another study under the overlay: its Frame of Reference is checked again.
  onModelChange<>(this, models_.document.changed, [this] {
    models_.fusion.setMainTime(models_.document.timePoint(), models_.document.timePoints());
    models_.fusion.setBase(models_.document.volume().get());
  });
  // A 4D overlay follows the study's time slider (time_follow.h's rule).
  onModelChange<>(this, models_.document.timeChanged, [this] {
    models_.fusion.setMainTime(models_.document.timePoint(), models_.document.timePoints());
  });
  // The 3D view raycasts the overlay in the same pass (the engine's fused dvr and mip).
  onModelChange<>(this, models_.fusion.changed, [this] {
    const FusionModel& f = models_.fusion;
    if (!f.active()) {
      scheduler_->setOverlay(nullptr, {});
      return;
    }
    try {
      scheduler_->setOverlay(f.overlay(), fusionTable(*f.overlay(), f.settings()));
    } catch (const std::exception& e) {  // settings are checked when set: a bug
      showError("Cannot show the overlay", QString::fromStdString(e.what()));
    }
  });
}

void MainWindow::openOverlay(const std::string& input, const LoadOptions& options) {
  overlayLoader_->load(input, options);
}

void MainWindow::wireCompare() {
  priorLoader_ = new LoadController(this);
  connect(priorLoader_, &LoadController::loaded, this,
          [this](VolumeSeries series, const QString& name, const QString& input) {
            if (series.empty()) return;
            // A session's alignment of this prior comes back after setPrior (which resets it).
            const auto saved = models_.comparison;
            const bool same = saved && saved->priorPath == input.toStdString() &&
                              saved->priorSeries == priorSeries_;
            const int ownTime = same ? saved->priorTimePoint : 0;  // a 4D prior's, if saved
            setCompareMode(true);
            models_.comparison =
                Session::Comparison{input.toStdString(), std::nullopt, ownTime, priorSeries_};
            compare_->setPrior(std::move(series), name, ownTime);
            if (same && saved->movingToFixed)
              compare_->comparison().setMovingToFixed(*saved->movingToFixed);  // checked rigid
            // The session's Link 3D look, then its prior camera (older sessions: linked, and
            // the camera the link gives).
            compare_->setLookLinked(same ? saved->linkLook : true);
            if (same && saved->priorCamera) {
              const CameraParams camera = *saved->priorCamera;
              compare_->prior().render.update(kCamera, [&](RenderParams& p) { p.camera = camera; });
            }
            // What the box and the camera are now (a change since is kept as it happens).
            models_.comparison->linkLook = compare_->lookLinked();
            models_.comparison->priorCamera = compare_->prior().render.params().camera;
            statusBar()->showMessage(compare_->statusText(), 30000);
          });
  connect(priorLoader_, &LoadController::failed, this,
          [this](const QString& m) { showError("Cannot open the prior", m); });
}

void MainWindow::openPrior(const std::string& input, const LoadOptions& options) {
  priorSeries_ = options.series;  // a session opens the same series again
  priorLoader_->load(input, options, QFileInfo(QString::fromStdString(input)).fileName());
}

void MainWindow::setCompareMode(bool on) {
  if (on && !compare_) {
    compare_ = new CompareView(models_, *scheduler_);
    auto* splitter = qobject_cast<QSplitter*>(centralWidget());
    splitter->insertWidget(0, compare_);
    splitter->setStretchFactor(0, 1);
    connect(compare_, &CompareView::closeRequested, this, [this] { setCompareMode(false); });
    connect(compare_, &CompareView::statusChanged, this,
            [this](const QString& t) { statusBar()->showMessage(t, 30000); });
    // Move prior's drags in Edit → Undo's order with the view's and the segments' edits.
    editOrder_->setPriorMoves(&compare_->moveHistory(), &compare_->comparison());
    // A series dropped on a column opens there (ReadingActions::dropSeries).
    if (seriesDrops_)
      for (QWidget* w : {static_cast<QWidget*>(&compare_->fixedView()),
                         static_cast<QWidget*>(&compare_->movingView()),
                         static_cast<QWidget*>(&compare_->fixed3dView()),
                         static_cast<QWidget*>(&compare_->moving3dView())})
        seriesDrops_->watch(w);
  }
  if (compare_) compare_->setVisible(on);
  grid_->setVisible(!on);
  // The study's 3D frames were planned for compare's 3D view (the same scheduler): the grid's
  // 3D view's size again.
  if (!on) scheduler_->setViewSize(volumeView_->size());
}

void MainWindow::addMultiVolumeActions(QMenu* file, QMenu* view) {
  if (file) {
    // (Here, not in wireCompare: the session actions exist once the menus are built.) A
    // session with a prior opens it beside the study, with its alignment.
    connect(sessions_, &SessionActions::sessionShown, this, [this] {
      if (models_.comparison && !models_.comparison->priorPath.empty()) {
        LoadOptions options;
        options.series = models_.comparison->priorSeries;
        openPrior(models_.comparison->priorPath, options);
      } else
        setCompareMode(false);
    });
    file->addAction("Open o&verlay volume…", this,
                    [this] {
                      const std::string input = askVolumeInput(this, "Open overlay volume");
                      if (!input.empty()) openOverlay(input);
                    })
        ->setObjectName("fileOpenOverlay");
    file->addAction("&Compare with prior…", this,
                    [this] {
                      const std::string input =
                          askVolumeInput(this, "Open the prior to compare with");
                      if (!input.empty()) openPrior(input);
                    })
        ->setObjectName("fileComparePrior");
  }
  if (view) {
    QAction* fusion = fusionDock_->toggleViewAction();
    fusion->setText("&Fusion");
    fusion->setObjectName("viewFusion");
    fusion->setToolTip("Show or hide the Fusion panel (an overlay volume over this one)");
    view->addAction(fusion);
    QAction* compare = view->addAction("&Compare mode / four views", this, [this] {
      if (!compare_ || !compare_->hasPrior()) {
        statusBar()->showMessage("Open a prior first: File → Compare with prior…", 8000);
        return;
      }
      setCompareMode(!compare_->isVisible());
    });
    compare->setObjectName("viewCompare");
  }
}

}  // namespace voxray::ui
