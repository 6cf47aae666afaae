#include "main_window.h"

#include <utility>

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>

#include "control_panel.h"
#include "coupling.h"
#include "export_dialog.h"
#include "gui_message.h"
#include "help_dialogs.h"
#include "measure_panel.h"
#include "movie_dialog.h"
#include "pacs_dialog.h"
#include "pacs_node_dialog.h"
#include "raw_import_dialog.h"
#include "reading_actions.h"
#include "recent_files.h"
#include "results_actions.h"
#include "segment_panel.h"
#include "series_drag.h"
#include "series_picker.h"
#include "session_state.h"
#include "settings_store.h"
#include "slice_view.h"
#include "study_browser_dialog.h"
#include "study_state.h"
#include "tf_editor_dialog.h"
#include "theme.h"
#include "time_panel.h"
#include "volume_view.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/sample_volume.h"
#include "voxray/io/volume_file.h"

namespace voxray::ui {

MainWindow::MainWindow(AppModels& models, const QString& device, QWidget* parent)
    : QMainWindow(parent),
      models_(models),
      history_(std::make_unique<ViewHistory>(models)),
      editOrder_(std::make_unique<EditOrder>(*history_, models.segmentation, &models.annotations)),
      historyListeners_(new QObject(this)) {
  setObjectName("mainWindow");
  setAcceptDrops(true);
  models_.device = device.toStdString();
  scheduler_ = new RenderScheduler(models.render, models.document, device, this);
  volumeView_ = new VolumeView(models.render, models.document, models.crosshair, *scheduler_);
  const Orientation orientations[] = {Orientation::Axial, Orientation::Coronal,
                                      Orientation::Sagittal};
  for (int i = 0; i < 3; ++i)
    slices_[size_t(i)] = new SliceView(orientations[i], models.document, models.crosshair,
                                       models.windowLevel, models.render);
  grid_ = new ViewGrid(volumeView_, slices_[0], slices_[1], slices_[2]);
  connect(volumeView_, &VolumeView::doubleClicked, this,
          [this] { grid_->toggleMaximised(volumeView_); });
  for (SliceView* s : slices_) {
    connect(s, &SliceView::doubleClicked, this, [this, s] { grid_->toggleMaximised(s); });
    // A clip edge dragged in a slice view is a drag of the 3D view's clip box too.
    connect(s, &SliceView::clipDragged, scheduler_, &RenderScheduler::beginInteraction);
    connect(s, &SliceView::clipDragEnded, scheduler_, &RenderScheduler::endInteraction);
  }

  auto* splitter = new QSplitter;
  splitter->addWidget(grid_);
  splitter->addWidget(makeControlPanel(models));
  splitter->setStretchFactor(0, 1);
  setCentralWidget(splitter);

  fpsLabel_ = new QLabel("no frame yet");
  fpsLabel_->setObjectName("fpsLabel");
  fpsLabel_->setToolTip(
      "Render time of the last 3D frame; frames per second while frames "
      "follow each other (a drag), none after a pause");
  deviceLabel_ = new QLabel("starting OpenCL …");
  deviceLabel_->setObjectName("deviceLabel");
  deviceLabel_->setToolTip("The OpenCL device that renders the 3D view");
  statusBar()->addPermanentWidget(fpsLabel_);
  statusBar()->addPermanentWidget(deviceLabel_);
  auto* progressLabel = new QLabel;  // lighting cinematic: samples and seconds so far
  progressLabel->setObjectName("progressLabel");
  statusBar()->addPermanentWidget(progressLabel);
  connect(scheduler_, &RenderScheduler::progressChanged, progressLabel, &QLabel::setText);
  // Each lighting model's cost on this scene is that of the frames it really rendered.
  connect(scheduler_, &RenderScheduler::frameReady, this, [this](std::shared_ptr<const Frame> f) {
    if (f->coarse) return;  // a coarse level's preview costs what the full volume's does not
    models_.lighting.recordFrame(f->params, f->stats, f->interactive);
  });
  connect(scheduler_, &RenderScheduler::statsChanged, this,
          [this](double fps, double ms, bool interactive) {
            stats_ = {true, fps, ms, interactive};
            fpsLabel_->setText(QString::fromStdString(formatFrameStats(stats_)));
          });
  connect(scheduler_, &RenderScheduler::deviceReady, this,
          [this](const QString& name) { deviceLabel_->setText(name); });
  // Issue 41 item 9: the first start compiles kernels for seconds; say so meanwhile.
  preparingLabel_ = new QLabel(kPreparingRenderer);
  preparingLabel_->setObjectName("preparingLabel");
  preparingLabel_->setToolTip(
      "The 3D view's OpenCL kernels are compiled on first use (cached afterwards); the "
      "slice views do not need them");
  statusBar()->addWidget(preparingLabel_);
  connect(scheduler_, &RenderScheduler::firstFullFrame, this,
          [this] { preparingLabel_->setText(""); });
  connect(scheduler_, &RenderScheduler::preparingChanged, this, [this](int left) {
    preparingLabel_->setText(left > 0 ? QString("Preparing the other 3D modes (%1 left)…").arg(left)
                                      : QString());
  });
  connect(scheduler_, &RenderScheduler::renderError, this,
          [this](const QString& message, bool rejected) {
            // The engine's message says what failed; the previous volume stays on screen.
            if (rejected) restorePreviousStudy(models_);
            preparingLabel_->setText("");
            showError(rejected ? "Cannot show this volume" : "Rendering failed", message);
          });

  movies_ = new MovieController(this);
  // Orbit frames on the view's device volume (issue 40 item 6): no second upload.
  movies_->setOnDevice(
      [s = scheduler_](const RenderParams& p, const Volume* v) { return s->renderOnDevice(p, v); });
  connect(movies_, &MovieController::written, this,
          [this](const QString& path) { statusBar()->showMessage("Movie saved: " + path, 10000); });
  connect(movies_, &MovieController::cancelled, this,
          [this] { statusBar()->showMessage("Movie export cancelled", 5000); });
  connect(movies_, &MovieController::failed, this,
          [this](const QString& message) { showError("Movie export failed", message); });
  loader_ = new LoadController(this);
  connect(loader_, &LoadController::loaded, this,
          [this](VolumeSeries series, const QString& name, const QString& input) {
            openedWithValues_ = !studyValues_.empty();
            try {
              openStudy(models_, std::move(series), name.toStdString(),
                        std::exchange(studyValues_, {}), loadingTimePoint_);
            } catch (const std::exception& e) {  // values were checked when given: a bug
              showError("Cannot open", QString::fromStdString(e.what()));
              return;
            }
            models_.source = std::exchange(loading_, {});
            if (!input.isEmpty()) addRecent(input.toStdString());
            showLoadWarnings();
            emit volumeShown();
          });
  connect(loader_, &LoadController::failed, this,
          [this](const QString& message) { showError("Cannot open", message); });
  connect(loader_, &LoadController::cancelled, this,
          [this] { statusBar()->showMessage("Loading cancelled", 5000); });
  wireMeasurements();
  wireSegments();
  wireTime();
  wireFusion();
  wireCompare();
  sessions_ = new SessionActions(*this, models_);
  buildMenus();
  // Issue 37: the Reading and Results menus (keys, layouts, hanging protocols; SR, KOS,
  // anonymised export), in files of their own.
  auto* reading = new ReadingActions(*this, models_);
  seriesDrops_ = new SeriesDropFilter(
      [reading](QWidget* view, const SeriesDrag& d) { reading->dropSeries(view, d); }, this);
  seriesDrops_->watch(volumeView_);
  for (SliceView* s : slices_) seriesDrops_->watch(s);
  auto* results = new ResultsActions(*this, models_, *reading);
  connect(reading, &ReadingActions::failed, this, &MainWindow::showError);
  connect(results, &ResultsActions::failed, this, &MainWindow::showError);
  qApp->installEventFilter(this);
  updateTitle();
  onModelChange<>(this, models_.document.changed, [this] { updateTitle(); });
  resize(defaultWindowSize(screen() ? screen()->availableGeometry().size() : QSize()));
}

QSize defaultWindowSize(QSize available) {
  // Room for the side panel unscrolled beside four views at 1920x1080 (issue 41 item 6:
  // 1400x900 scrolled it and clipped the scale bars' labels); smaller screens get all of it.
  const QSize wanted(1880, 1000);
  if (available.isEmpty()) return wanted;
  return wanted.boundedTo(available - QSize(20, 40));
}

MainWindow::~MainWindow() {
  qApp->removeEventFilter(this);
  // An export renders through the scheduler's worker: it stops first (children go in the
  // order they were made, the scheduler before the movie controller).
  delete movies_;
  movies_ = nullptr;
  delete historyListeners_;
}

void MainWindow::wireMeasurements() {
  for (SliceView* s : slices_) {
    s->setMeasurements(&models_.measurements);
    s->setAnnotationModel(&models_.annotations);
  }
  volumeView_->setMeasurements(&models_.measurements);
  measureDock_ = makeMeasurementDock(models_.measurements, models_.annotations, models_.document);
  addDockWidget(Qt::RightDockWidgetArea, measureDock_);
  connect(volumeView_, &VolumeView::pickMissed, this,
          [this](const QString& m) { statusBar()->showMessage(m, 5000); });
  // Measurements are voxel positions of one volume: another volume starts without them.
  onModelChange<>(this, models_.document.changed, [this] { models_.measurements.clear(); });
}

void MainWindow::setErrorSink(ErrorSink sink) {
  errorSink_ = std::move(sink);
  if (errorSink_)
    segmentPanel_->setErrorSink([this](const QString& t, const QString& m) { errorSink_(t, m); });
  else
    segmentPanel_->setErrorSink({});
}

void MainWindow::wireSegments() {
  for (SliceView* s : slices_) {
    s->setSegmentation(&models_.segmentation, &models_.segmentTools);
    connect(s, &SliceView::segmentToolFailed, this, [this](const QString& m) {
      statusBar()->showMessage(QString::fromStdString(guiMessage(m.toStdString())), 8000);
    });
  }
  volumeView_->setSegmentation(&models_.segmentation, &models_.segmentTools);
  connect(volumeView_, &VolumeView::segmentToolFailed, this, [this](const QString& m) {
    statusBar()->showMessage(QString::fromStdString(guiMessage(m.toStdString())), 8000);
  });
  segmentDock_ = makeSegmentDock(models_, &segmentPanel_);
  connect(segmentPanel_, &SegmentPanel::editTfRequested, this,
          [this](uint8_t label) { openTfEditor(label); });
  addDockWidget(Qt::RightDockWidgetArea, segmentDock_);
  tabifyDockWidget(measureDock_, segmentDock_);
  measureDock_->raise();
  // The 3D view's copy of the label map follows every edit (the edited box only).
  onModelChange<>(this, models_.segmentation.changed,
                  [this] { scheduler_->updateSegmentation(models_.segmentation); });
}

void MainWindow::openTfEditor(uint8_t label) {
  if (!tfEditor_) tfEditor_ = new TfEditorDialog(models_, scheduler_, this);
  tfEditor_->editTable(label);
  tfEditor_->show();
  tfEditor_->raise();
}

void MainWindow::showLoadWarnings() {
  // Every warning at once (a PET's missing SUV attribute among them): one message each would
  // replace the one before it unread.
  QStringList lines;
  for (const auto& w : models_.document.volume()->warnings) {
    const QString line = QString::fromStdString(guiMessage(w));
    if (!lines.contains(line)) lines << line;
  }
  if (lines.isEmpty()) return;
  statusBar()->showMessage(lines.join("  ·  "), 30000);
  statusBar()->setToolTip(lines.join("\n"));
}

void MainWindow::wireTime() {
  timePanel_ = new TimePanel(models_);
  timeDock_ = new QDockWidget("Time");
  timeDock_->setObjectName("timeDock");
  timeDock_->setWidget(timePanel_);
  addDockWidget(Qt::BottomDockWidgetArea, timeDock_);
  timeDock_->hide();
  connect(timePanel_, &TimePanel::csvWritten, this,
          [this](const QString& path) { statusBar()->showMessage("Curve saved: " + path, 10000); });
  connect(timePanel_, &TimePanel::csvFailed, this,
          [this](const QString& message) { showError("Cannot export the curve", message); });
  // A 4D series brings the panel up; a 3D volume puts it away.
  onModelChange<>(this, models_.document.changed,
                  [this] { timeDock_->setVisible(models_.document.timePoints() > 1); });
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("Study &browser…", QKeySequence("Ctrl+B"), this, [this] { showStudyBrowser(); });
  file->addAction("Open &DICOM folder…", QKeySequence::Open, this, &MainWindow::openDicomFolder);
  file->addAction("Open &raw volume…", QKeySequence("Ctrl+R"), this, &MainWindow::openRaw);
  file->addAction("Open &sample CT", this, [this] { open(kSampleCtInput, {}); });
  file->addAction("Open volume &file (NIfTI, NRRD, MetaImage)…", QKeySequence("Ctrl+Shift+O"), this,
                  &MainWindow::openVolumeFile);
  file->addAction("Open head &phantom", this, [this] { open("", {}); });
  file->addAction("Open &session…", QKeySequence("Ctrl+Alt+O"), sessions_, &SessionActions::open);
  file->addAction("Open from &PACS…", QKeySequence("Ctrl+Shift+P"), this,
                  &MainWindow::openFromPacs);
#ifdef VOXRAY_HAS_DICOM
  // Issue 41: the node editor without going through Open from PACS first.
  file->addAction("PACS &nodes…", this,
                  [this] {
                    PacsNodeDialog editor(this);
                    editor.exec();
                  })
      ->setObjectName("filePacsNodes");
#endif
  addMultiVolumeActions(file, nullptr);
  recentMenu_ = file->addMenu("Open &recent");
  rebuildRecentMenu();
  file->addSeparator();
  file->addAction("Sa&ve session…", QKeySequence::Save, sessions_, &SessionActions::save);
  file->addAction("&Export screenshot…", QKeySequence("Ctrl+E"), this,
                  &MainWindow::exportScreenshot);
  file->addAction("Export &movie…", this, &MainWindow::exportMovie);
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);
  QMenu* view = menuBar()->addMenu("&View");
  view->addAction("&Maximise / restore focused view", QKeySequence("F11"), this, [this] {
    QWidget* focused = QApplication::focusWidget();
    grid_->toggleMaximised(focused ? focused : volumeView_);
  });
  // A closed dock comes back from here (its own action: checked while it is shown).
  QAction* measurements = measureDock_->toggleViewAction();
  measurements->setText("&Measurements");
  measurements->setObjectName("viewMeasurements");
  measurements->setToolTip("Show or hide the Measurements panel");
  view->addAction(measurements);
  QAction* segments = segmentDock_->toggleViewAction();
  segments->setText("&Segments");
  segments->setObjectName("viewSegments");
  segments->setShortcut(QKeySequence("Ctrl+Shift+S"));
  segments->setToolTip("Show or hide the Segments panel (the segment editor)");
  view->addAction(segments);
  QAction* time = timeDock_->toggleViewAction();
  time->setText("T&ime series");
  time->setObjectName("viewTime");
  time->setToolTip("Show or hide the time panel of a 4D series");
  view->addAction(time);
  addMultiVolumeActions(nullptr, view);
  QAction* studyText = view->addAction("&Patient and study text", this,
                                       [this](bool on) { models_.render.setStudyText(on); });
  studyText->setCheckable(true);
  studyText->setObjectName("viewStudyText");
  studyText->setToolTip(
      "Show the patient's name, ID and the study in the views' corners "
      "(never in exports unless ticked there)");
  // Issue 35: shaping the dvr table on the volume's histogram.
  view->addAction("&Transfer function editor…", QKeySequence("Ctrl+T"), this,
                  [this] { openTfEditor(0); })
      ->setObjectName("viewTfEditor");
  view->addAction("Reset slice &planes", QKeySequence("Ctrl+Shift+R"), this,
                  [this] { models_.crosshair.resetRotation(); })
      ->setToolTip("Turn the slice views back to the acquisition planes");
  QMenu* theme = view->addMenu("&Theme");
  auto* themes = new QActionGroup(theme);
  for (const QString& name : themeNames()) {
    QAction* a = theme->addAction(name, this, [this, name] {
      theme_ = name;
      applyTheme(name);
    });
    a->setCheckable(true);
    a->setChecked(name == theme_);
    a->setObjectName("theme" + name);
    themes->addAction(a);
  }
  QMenu* edit = menuBar()->addMenu("&Edit");
  // With the focus in the Segments panel, the segment editor's own steps; else the last edit
  // of the view or the segments.
  auto segmentsFocused = [this] {
    return segmentDock_ && segmentDock_->isAncestorOf(QApplication::focusWidget());
  };
  QAction* undo = edit->addAction("&Undo", QKeySequence::Undo, this, [this, segmentsFocused] {
    if (segmentsFocused() && models_.segmentation.canUndo())
      editOrder_->undo(EditOrder::Source::Segments);
    else
      editOrder_->undo();
  });
  QAction* redo =
      edit->addAction("&Redo", QKeySequence("Ctrl+Shift+Z"), this, [this, segmentsFocused] {
        if (segmentsFocused() && models_.segmentation.canRedo())
          editOrder_->redo(EditOrder::Source::Segments);
        else
          editOrder_->redo();
      });
  undo->setObjectName("editUndo");
  redo->setObjectName("editRedo");
  auto enable = [this, undo, redo] {
    undo->setEnabled(editOrder_->canUndo());
    redo->setEnabled(editOrder_->canRedo());
    const std::string u = editOrder_->undoText(), r = editOrder_->redoText();
    undo->setToolTip(u.empty() ? "Undo the last change of the view (camera, clip box, light, "
                                 "window/level) or of the segments"
                               : QString::fromStdString(u));
    redo->setToolTip(r.empty() ? "Redo the change last undone" : QString::fromStdString(r));
  };
  enable();
  onModelChange<>(historyListeners_, editOrder_->changed, enable);
  menuBar()->insertMenu(view->menuAction(), edit);
  QMenu* help = menuBar()->addMenu("&Help");
  help->addAction("&Keyboard shortcuts", QKeySequence::HelpContents, this,
                  [this] { showShortcuts(this, *menuBar()); });
  help->addAction("&About Voxray", this, [this] { showAbout(this, deviceLabel_->text()); });
}

bool MainWindow::eventFilter(QObject* watched, QEvent* e) {
  // Gestures start by presses inside this window only (a dialog's clicks are not view
  // changes) but end at any release: a press on the menu bar is released in the menu.
  if (e->type() == QEvent::MouseButtonPress) {
    auto* w = qobject_cast<QWidget*>(watched);
    if (w && w->window() == this) history_->beginGesture();
  } else if (e->type() == QEvent::MouseButtonRelease) {
    history_->endGesture();
  }
  return QMainWindow::eventFilter(watched, e);
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  QSettings s;
  for (const auto& entry : loadRecent(s)) {
    QString path = QString::fromStdString(entry);
    recentMenu_->addAction(path, this, [this, entry] {
      if (isSessionPath(entry)) {
        sessions_->openFile(entry);
        return;
      }
      QSettings settings;
      LoadOptions o;
      o.raw = loadRawLayoutFor(settings, entry);
      open(entry, o);
    });
  }
  recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

void MainWindow::addRecent(const std::string& path) {
  QSettings s;
  saveRecent(s, pushRecent(loadRecent(s), path));
  rebuildRecentMenu();
}

void MainWindow::open(const std::string& input, const LoadOptions& options,
                      const std::map<std::string, std::string>& studyValues) {
  if (loader_->busy()) return;  // the loader ignores it too: keep the running load's values
  studyValues_ = studyValues;
  loading_ = {input, flagsFromLoadOptions(options)};
  loadingTimePoint_ = options.timePoint.value_or(0);
  QString name =
      input.empty() ? QString("head phantom") : QFileInfo(QString::fromStdString(input)).fileName();
  if (options.raw) {
    QSettings s;
    saveRawLayoutFor(s, input, *options.raw);
  }
  loader_->load(input, options, name);
}

void MainWindow::openDicomFolder() {
  QSettings s;
  QString dir = QFileDialog::getExistingDirectory(
      this, "Open DICOM folder", s.value("lastFolder", QDir::homePath()).toString());
  if (dir.isEmpty()) return;
  s.setValue("lastFolder", dir);
  // An OME-Zarr folder is one volume, not a DICOM folder to list: open it directly.
  if (isOmeZarr(dir.toStdString())) {
    open(dir.toStdString(), {});
    return;
  }
  auto choice = pickSeries(this, dir.toStdString());
  if (choice) open(dir.toStdString(), *choice);
}

void MainWindow::openFromPacs() {
#ifdef VOXRAY_HAS_DICOM
  PacsDialog dialog(this);
  if (dialog.exec() != QDialog::Accepted) return;
  openRetrieved(dialog.chosen().folder, dialog.chosen().seriesUid);
#endif
}

void MainWindow::openRetrieved(const std::string& folder, const std::string& series) {
#ifdef VOXRAY_HAS_STUDYDB
  // Into the study database too (as voxray-cli pacs get --db): found locally the next time.
  if (StudyBrowserDialog* b = studyBrowser()) b->storeRetrieved(QString::fromStdString(folder));
#endif
  LoadOptions options;
  options.series = series;
  if (options.series.empty()) {  // a whole study: its series go to the picker
    auto choice = pickSeries(this, folder);
    if (!choice) return;
    options = *choice;
  }
  open(folder, options);
}

StudyBrowserDialog* MainWindow::studyBrowser() {
#ifdef VOXRAY_HAS_STUDYDB
  if (!studyBrowser_) {
    studyBrowser_ = new StudyBrowserDialog(this);
    studyBrowser_->setErrorSink(
        [this](const QString& title, const QString& message) { showError(title, message); });
    connect(studyBrowser_, &StudyBrowserDialog::openRequested, this,
            [this](const QString& folder, const QString& series, bool newWindow) {
              LoadOptions options;
              options.series = series.toStdString();
              if (newWindow)
                openInNewWindow(folder.toStdString(), options);
              else
                open(folder.toStdString(), options);
            });
    // The browser's PACS page: stored by the browser itself, then opened here.
    connect(studyBrowser_, &StudyBrowserDialog::pacsRetrieved, this,
            [this](const QString& folder, const QString& series) {
              LoadOptions options;
              options.series = series.toStdString();
              if (options.series.empty()) {
                auto choice = pickSeries(this, folder.toStdString());
                if (!choice) return;
                options = *choice;
              }
              open(folder.toStdString(), options);
            });
  }
  return studyBrowser_;
#else
  return nullptr;
#endif
}

StudyBrowserDialog* MainWindow::showStudyBrowser() {
  StudyBrowserDialog* b = studyBrowser();
  if (!b) {
    statusBar()->showMessage("This build has no study database (built without DICOM)", 5000);
    return nullptr;
  }
  b->show();
  b->raise();
  b->activateWindow();
  return b;
}

MainWindow* MainWindow::openInNewWindow(const std::string& input, const LoadOptions& options) {
  // Its own models: the second window is a workstation of its own (the comparison views of
  // the multi-volume work will replace this).
  auto* models = new AppModels;
  auto* w = new MainWindow(*models, QString::fromStdString(models_.device));
  w->setAttribute(Qt::WA_DeleteOnClose);
  // QWidget sends destroyed before deleting its children (the views bound to the models):
  // the models go once the whole window is gone.
  connect(w, &QObject::destroyed, qApp,
          [models] { QTimer::singleShot(0, qApp, [models] { delete models; }); });
  if (errorSink_) w->setErrorSink(errorSink_);
  w->show();
  w->open(input, options);
  emit secondWindowOpened(w);
  return w;
}

void MainWindow::openRaw() {
  QSettings s;
  auto request = RawImportDialog::ask(this, s.value("lastFolder", QDir::homePath()).toString(),
                                      [](const std::string& path) {
                                        QSettings settings;
                                        return loadRawLayoutFor(settings, path);
                                      });
  if (!request) return;
  s.setValue("lastFolder", QFileInfo(request->first).absolutePath());
  LoadOptions o;
  o.raw = request->second;
  open(request->first.toStdString(), o);
}

void MainWindow::openVolumeFile() {
  QSettings s;
  QStringList patterns;  // the extensions io declares, so a new format needs no edit here
  for (const auto& e : volumeFileExtensions()) patterns << "*" + QString::fromStdString(e);
  const QString file = QFileDialog::getOpenFileName(
      this, "Open volume file", s.value("lastFolder", QDir::homePath()).toString(),
      "NIfTI, NRRD, MetaImage (" + patterns.join(' ') + ");;All files (*)");
  if (file.isEmpty()) return;
  s.setValue("lastFolder", QFileInfo(file).absolutePath());
  open(file.toStdString(), {});
}

void MainWindow::exportScreenshot() {
  ExportDialog dialog(this, *scheduler_, *volumeView_, slices_);
  if (models_.document.volume()) dialog.setStudy(models_.document.volume()->study);
  if (errorSink_) dialog.setErrorSink([this](const QString& m) { errorSink_("Export failed", m); });
  dialog.exec();
}

void MainWindow::exportMovie() {
  MovieDialog dialog(this, models_, *movies_, QString::fromStdString(models_.device));
  if (errorSink_)
    dialog.setErrorSink([this](const QString& m) { errorSink_("Cannot export the movie", m); });
  dialog.exec();
}

void MainWindow::showError(const QString& title, const QString& cliMessage) {
  // io and engine word their errors for voxray-cli: here the fields have other names.
  QString message = QString::fromStdString(guiMessage(cliMessage.toStdString()));
  if (errorSink_) {
    errorSink_(title, message);
    return;
  }
  QMessageBox box(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
  box.exec();
}

void MainWindow::updateTitle() {
  setWindowTitle(QString::fromStdString(formatWindowTitle(models_.document.name())));
}

void MainWindow::restoreSettings() {
  QSettings s;
  restoreGeometry(s.value("window/geometry").toByteArray());
  grid_->setMaximised(s.value("window/maximisedView", -1).toInt());
  theme_ = s.value("window/theme", themeNames().front()).toString();
  applyTheme(theme_);
  for (QAction* a : menuBar()->findChildren<QAction*>("theme" + theme_)) a->setChecked(true);
  loadModelSettings(s, models_);
}

void MainWindow::closeEvent(QCloseEvent* e) {
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/maximisedView", grid_->maximisedIndex());
  s.setValue("window/theme", theme_);
  saveModelSettings(s, models_);
  e->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (urls.isEmpty() || !urls.first().isLocalFile()) return;
  std::string path = urls.first().toLocalFile().toStdString();
  QSettings s;
  LoadOptions o;
  o.raw = loadRawLayoutFor(s, path);  // a raw file opened before keeps its layout
  open(path, o);
}

}  // namespace voxray::ui
