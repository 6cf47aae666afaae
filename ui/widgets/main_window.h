#pragma once
// The workstation window. It composes views, panel, menus and status bar and wires them
// to the models; it computes nothing itself (models and small helpers do).
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <QLabel>
#include <QMainWindow>
#include <QMenu>

#include "app_models.h"
#include "edit_order.h"
#include "load_controller.h"
#include "movie_controller.h"
#include "render_scheduler.h"
#include "session_actions.h"
#include "status_text.h"
#include "view_grid.h"
#include "view_history.h"

class QDockWidget;

namespace voxray::ui {

class CompareView;
class FusionPanel;
class LoadController;
class OverlayLoader;
class SegmentPanel;
class SeriesDropFilter;
class SliceView;
class StudyBrowserDialog;
class TimePanel;
class TfEditorDialog;
class VolumeView;

// What the status bar says until the first 3D frame (and a test looks for).
inline const QString kPreparingRenderer = "Preparing the 3D renderer…";

// The window's first size (before a saved geometry): 1880x1000, less where the screen's
// AVAILABLE area is smaller (empty: unknown).
QSize defaultWindowSize(QSize available);

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  MainWindow(AppModels& models, const QString& device, QWidget* parent = nullptr);
  ~MainWindow() override;

  VolumeView& volumeView() { return *volumeView_; }
  SliceView& sliceView(int i) { return *slices_[size_t(i)]; }  // axial, coronal, sagittal
  RenderScheduler& scheduler() { return *scheduler_; }
  LoadController& loader() { return *loader_; }
  ViewHistory& history() { return *history_; }
  ViewGrid& grid() { return *grid_; }
  SessionActions& sessions() { return *sessions_; }
  MovieController& movies() { return *movies_; }
  SegmentPanel& segments() { return *segmentPanel_; }
  QDockWidget* segmentDock() { return segmentDock_; }
  TimePanel& timePanel() { return *timePanel_; }
  QDockWidget& timeDock() { return *timeDock_; }
  // Issue 36 (main_window_multi.cpp): fusion and compare.
  FusionPanel& fusionPanel() { return *fusionPanel_; }
  QDockWidget& fusionDock() { return *fusionDock_; }
  CompareView* compareView() { return compare_; }  // null until a prior is opened
  // INPUT (anything the loader reads) as the fusion overlay over the study, on its own thread.
  void openOverlay(const std::string& input, const LoadOptions& options = {});
  // INPUT as the prior beside the study: the comparison mode, once loaded.
  void openPrior(const std::string& input, const LoadOptions& options = {});
  void setCompareMode(bool on);  // the two columns instead of the four views, or back
  // What makes a view take series dragged from the study browser (a series cell's view too).
  SeriesDropFilter* seriesDrops() const { return seriesDrops_; }

  // Opens INPUT (DICOM, raw with options.raw, or "" for the phantom) on the load thread;
  // once loaded it starts from its own defaults, with STUDYVALUES on top (openStudy).
  void open(const std::string& input, const LoadOptions& options,
            const std::map<std::string, std::string>& studyValues = {});
  void restoreSettings();
  // File → Study browser… (Ctrl+B): shows the local study database's browser, made when
  // first asked (null in a build without the database).
  StudyBrowserDialog* showStudyBrowser();
  // Opens INPUT in a second window of its own (a prior beside the current study); the window
  // deletes itself and its models when closed.
  MainWindow* openInNewWindow(const std::string& input, const LoadOptions& options);
  // PATH (a volume or a session) at the top of File → Open recent.
  void addRecent(const std::string& path);

  // Whether the volume last shown came with values of its own (a session): the hanging
  // protocols leave such a view as it was saved.
  bool openedWithValues() const { return openedWithValues_; }

  // Where load, render and export errors go: a modal message box unless a test (or an
  // embedding) sets its own sink.
  using ErrorSink = std::function<void(const QString& title, const QString& message)>;
  void setErrorSink(ErrorSink sink);

 signals:
  void volumeShown();  // a loaded volume became the document
  void secondWindowOpened(MainWindow* window);

 protected:
  // Every mouse press to release in this window is one undo step (a drag, a slider pulled).
  bool eventFilter(QObject* watched, QEvent* e) override;
  void closeEvent(QCloseEvent*) override;
  void dragEnterEvent(QDragEnterEvent*) override;
  void dropEvent(QDropEvent*) override;

 private:
  void buildMenus();
  void wireMeasurements();  // views, side panel and 3D picks share models_.measurements
  void wireSegments();      // the Segments dock, the slice views' overlays and tools, the 3D view
  void wireTime();
  void wireFusion();   // main_window_multi.cpp
  void wireCompare();  // main_window_multi.cpp
  void addMultiVolumeActions(QMenu* file, QMenu* view);
  void showLoadWarnings();  // every loader warning at once in the status bar
  void rebuildRecentMenu();
  void openDicomFolder();
  void openRaw();
  void openFromPacs();
  StudyBrowserDialog* studyBrowser();  // made when first needed
  // A PACS retrieval (FOLDER, its series; empty: a whole study, for the series picker):
  // stored in the study database, then opened.
  void openRetrieved(const std::string& folder, const std::string& series);
  void openVolumeFile();
  void exportScreenshot();
  void exportMovie();
  void showError(const QString& title, const QString& message);
  void updateTitle();
  // The transfer-function editor (made when first asked) on the volume's table (0) or on
  // segment LABEL's own (the Segments panel's TF… Edit).
  void openTfEditor(uint8_t label);

  AppModels& models_;
  RenderScheduler* scheduler_;
  VolumeView* volumeView_;
  std::array<SliceView*, 3> slices_{};
  ViewGrid* grid_;
  LoadController* loader_;
  QLabel* fpsLabel_;
  QLabel* deviceLabel_;
  QLabel* preparingLabel_;  // kPreparingRenderer, then the background builds left
  QMenu* recentMenu_ = nullptr;
  QString theme_ = "System";  // View → Theme, saved with the window layout
  std::unique_ptr<ViewHistory> history_;
  // Edit → Undo/Redo: the view's and the segment editor's steps in the order made.
  std::unique_ptr<EditOrder> editOrder_;
  // Owns the connections to history_; deleted before history_ (children go after members).
  QObject* historyListeners_;
  FrameRateStats stats_;
  ErrorSink errorSink_;
  std::map<std::string, std::string> studyValues_;  // for the volume being loaded
  bool openedWithValues_ = false;
  SessionActions* sessions_ = nullptr;
  QDockWidget* measureDock_ = nullptr;  // View → Measurements reopens it
  QDockWidget* segmentDock_ = nullptr;  // View → Segments
  SegmentPanel* segmentPanel_ = nullptr;
  QDockWidget* timeDock_ = nullptr;  // a 4D series' time slider, play and curve
  TimePanel* timePanel_ = nullptr;
  QDockWidget* fusionDock_ = nullptr;  // the Fusion group
  FusionPanel* fusionPanel_ = nullptr;
  OverlayLoader* overlayLoader_ = nullptr;
  LoadController* priorLoader_ = nullptr;  // the prior for compare, beside the study's loader
  CompareView* compare_ = nullptr;
  // Series dragged from the study browser onto the grid's and compare's views (series_drag.h).
  SeriesDropFilter* seriesDrops_ = nullptr;
  std::string priorSeries_;             // the series the prior loader opens (LoadOptions::series)
  int loadingTimePoint_ = 0;            // the time point to show first of the input being loaded
  SessionInput loading_;                // the input being loaded, for AppModels::source
  MovieController* movies_ = nullptr;   // File → Export movie, in the background
  TfEditorDialog* tfEditor_ = nullptr;  // View → Transfer function editor, made when first asked
  StudyBrowserDialog* studyBrowser_ = nullptr;  // File → Study browser, made when first asked
};

}  // namespace voxray::ui
