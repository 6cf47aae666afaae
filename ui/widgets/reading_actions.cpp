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

namespace {
const char* kLastLayoutKey = "reading/lastLayout";

// Whether the compare prior is SERIES of FOLDER (a session reads its paths normalised).
bool priorIs(const AppModels& m, const std::string& folder, const std::string& series) {
  namespace fs = std::filesystem;
  return m.comparison && m.comparison->priorSeries == series &&
         fs::path(m.comparison->priorPath).lexically_normal() ==
             fs::path(folder).lexically_normal();
}
}  // namespace

std::string qtKeyNormaliser(const std::string& key) {
  const QKeySequence k =
      QKeySequence::fromString(QString::fromStdString(key), QKeySequence::PortableText);
  // One key only: a chord ("Ctrl+K, D") would wait for its second key in the views.
  if (k.isEmpty() || k.count() != 1 || k[0].key() == Qt::Key_unknown) return "";
  return k.toString(QKeySequence::PortableText).toStdString();
}

ReadingActions::ReadingActions(MainWindow& window, AppModels& models)
    : QObject(&window),
      window_(window),
      models_(models),
      cells_(std::make_unique<SeriesCells>(models.document, models.crosshair, models.render)) {
  setObjectName("readingActions");
  configFolder_ = QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation);
  buildMenu();
  loadUserFiles();
  connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
    for (int i = 0; i < 3; ++i)
      if (now == &window_.sliceView(i)) focusedSlice_ = i;
  });
  // The last layout the user chose, for a start where no hanging protocol matches.
  if (const auto last = parseLayout(QSettings().value(kLastLayoutKey).toString().toStdString()))
    setReading(ReadingLayout{*last, {}});
  // A study the user opens (not a session: it brings its own view) hangs by the rules.
  connect(&window_, &MainWindow::volumeShown, this, [this] {
    // Another study: the cells of the last one close, and their placement with them (a
    // session opens its own again; a rule places the new study's).
    if (!cells_->empty() && models_.source.path != cellsFolder_)
      setReading(ReadingLayout{reading_.layout, {}});  // its placement goes with them
    if (pendingPlacement_) {                           // the series a rule placed is shown now
      ReadingLayout r = *pendingPlacement_;
      pendingPlacement_.reset();
      const std::string shown = shownSeries(r.layout, r.placed).value_or("");
      hang(r, shown);
      if (pendingRule_) {
        const HangingRule rule = *pendingRule_;
        pendingRule_.reset();
        applyLook(&rule);
      }
      return;
    }
    if (!window_.openedWithValues() && !window_.sessions().showingSession()) applyHangingProtocol();
  });
  auto dropPending = [this] {
    pendingPlacement_.reset();
    pendingRule_.reset();
  };
  connect(&window_.loader(), &LoadController::failed, this, dropPending);
  connect(&window_.loader(), &LoadController::cancelled, this, dropPending);
}

ReadingActions::~ReadingActions() {
  // The cells' views and loaders go before the models they are bound to.
  for (const auto& [view, w] : cellViews_)
    if (w) delete w->parentWidget();  // the view and its name
  if (cell3d_) delete cell3d_->parentWidget();
  cell3dScheduler_.reset();
  for (const auto& [view, l] : cellLoaders_) delete l.data();
  cells_.reset();
}

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
void ReadingActions::setConfigFolder(const QString& folder) {
  configFolder_ = folder;
  loadUserFiles();
}

QString ReadingActions::hangingProtocolsPath() const {
  return QDir(configFolder_).filePath("hanging-protocols.json");
}

QString ReadingActions::keymapPath() const { return QDir(configFolder_).filePath("keymap.json"); }

void ReadingActions::loadUserFiles() {
  keymap_ = ReadingKeymap();
  protocols_ = defaultHangingProtocols();
  // Said once the window is up (the constructor's signals reach no one yet).
  auto later = [this](QString title, QString message) {
    QTimer::singleShot(0, this, [this, title, message] { emit failed(title, message); });
  };
  try {
    keymap_.load(keymapPath().toStdString(), qtKeyNormaliser);
  } catch (const std::exception& e) {
    later("Keymap not used",
          QString::fromStdString(e.what()) + "\nThe default keys apply until it is fixed.");
  }
  try {
    protocols_ = loadHangingProtocols(hangingProtocolsPath().toStdString());
  } catch (const std::exception& e) {
    later("Hanging protocols not used",
          QString::fromStdString(e.what()) + "\nThe default rules apply until it is fixed.");
  }
  applyKeys();
}

void ReadingActions::bind(const std::string& id, QAction* a) {
  actions_[id] = a;
  a->setObjectName(QString::fromStdString("reading-" + id));
  // Only while the views have the focus: the panel's fields keep their digits and letters.
  a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  window_.grid().addAction(a);
  a->setShortcut(QKeySequence::fromString(QString::fromStdString(keymap_.key(id)),
                                          QKeySequence::PortableText));
}

QAction* ReadingActions::action(const std::string& id) const {
  auto it = actions_.find(id);
  return it == actions_.end() ? nullptr : it->second;
}

void ReadingActions::applyKeys() {
  for (auto& [id, a] : actions_)
    a->setShortcut(QKeySequence::fromString(QString::fromStdString(keymap_.key(id)),
                                            QKeySequence::PortableText));
}

void ReadingActions::buildMenu() {
  QMenu* menu = new QMenu("Rea&ding", &window_);
  QAction* help = nullptr;
  for (QAction* a : window_.menuBar()->actions())
    if (a->text().remove('&') == "Help") help = a;
  window_.menuBar()->insertMenu(help, menu);

  QMenu* layouts = menu->addMenu("&Layout");
  auto* group = new QActionGroup(this);
  for (ViewLayout l : viewLayouts()) {
    QAction* a = layouts->addAction(QString::fromStdString(layoutTitle(l)), this,
                                    [this, l] { setLayout(l); });
    a->setCheckable(true);
    a->setChecked(l == reading_.layout);
    group->addAction(a);
    bind("layout-" + layoutName(l), a);
  }
  QMenu* windows = menu->addMenu("&Window preset");
  for (size_t i = 0; i < numberKeyWindows().size(); ++i) {
    const std::string name = numberKeyWindows()[i];
    QAction* a = windows->addAction(QString::fromStdString(name), this,
                                    [this, name] { models_.windowLevel.applyPreset(name); });
    bind("window-" + std::to_string(i + 1), a);
  }
  menu->addSeparator();
  bind("next-series", menu->addAction("&Next series", this, [this] { stepSeries(1); }));
  bind("previous-series", menu->addAction("&Previous series", this, [this] { stepSeries(-1); }));
  bind("next-study", menu->addAction("Next s&tudy", this, [this] { stepStudy(1); }));
  bind("previous-study", menu->addAction("Previous st&udy", this, [this] { stepStudy(-1); }));
  bind("page-forward", menu->addAction("Page &forward", this, [this] { page(1); }));
  bind("page-back", menu->addAction("Page &back", this, [this] { page(-1); }));
  menu->addSeparator();
  const std::pair<const char*, MeasureTool> tools[] = {
      {"tool-probe", MeasureTool::None},  {"tool-distance", MeasureTool::Distance},
      {"tool-angle", MeasureTool::Angle}, {"tool-roi", MeasureTool::Ellipse},
      {"tool-text", MeasureTool::Text},   {"tool-arrow", MeasureTool::Arrow}};
  const char* toolTitles[] = {"P&robe (pointer)", "&Distance",        "&Angle",
                              "R&OI (ellipse)",   "Te&xt annotation", "Arro&w annotation"};
  for (size_t i = 0; i < std::size(tools); ++i) {
    const MeasureTool t = tools[i].second;
    bind(tools[i].first,
         menu->addAction(toolTitles[i], this, [this, t] { models_.measurements.setTool(t); }));
  }
  menu->addSeparator();
  // Show series in this view: the study's series, listed when the menu opens.
  QMenu* series = menu->addMenu("Show &series in this view");
  series->setObjectName("readingShowSeries");
  connect(series, &QMenu::aboutToShow, this, [this, series] { fillSeriesMenu(series); });
  menu->addSeparator();
  menu->addAction("&Hanging protocols…", this, [this] { showHangingProtocolEditor(); })
      ->setObjectName("readingHangingProtocols");
  menu->addAction("&Keymap…", this, [this] { showKeymapEditor(); })->setObjectName("readingKeymap");
}

void ReadingActions::setLayout(ViewLayout l) {
  QSettings().setValue(kLastLayoutKey, QString::fromStdString(layoutName(l)));
  pendingPlacement_.reset();
  pendingRule_.reset();
  if (besideShown_) {  // every view shows the open volume again: the second series goes
    besideShown_ = false;
    models_.comparison.reset();
    window_.setCompareMode(false);
  }
  setReading(ReadingLayout{l, {}});  // no series placed: the cells close
}

void ReadingActions::setReading(const ReadingLayout& r) {
  reading_ = r;
  // One or two series: the grid's views and compare's columns show them; no cells.
  if (seriesInCells(r).size() <= 2)
    for (GridView c : cells_->leaving({})) closeCell(c);
  window_.grid().arrange(visibleCells(r));
  if (QAction* a = action("layout-" + layoutName(r.layout))) a->setChecked(true);
  if (const QString notes = emptyViewsText(); !notes.isEmpty()) status(notes);
  emit layoutChanged();
}

#ifdef VOXRAY_HAS_DICOM
namespace {
// The study folder's volume series in the study's order, and which of them is open (-1: none).
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
}  // namespace
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

GridView ReadingActions::focusedGridView() const {
  return std::array{GridView::Axial, GridView::Coronal, GridView::Sagittal}[size_t(focusedSlice_)];
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

QString ReadingActions::emptyViewsText() const {
  QStringList notes;
  for (const std::string& n : emptyViewNotes(reading_)) notes << QString::fromStdString(n);
  return notes.isEmpty() ? QString() : "Views left empty: " + notes.join("  ·  ");
}

SliceView& ReadingActions::focusedSlice() const { return window_.sliceView(focusedSlice_); }

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

void ReadingActions::showKeymapEditor() {
  JsonTextDialog d(
      &window_, "Reading keys",
      "The reading actions' keys (Qt's key names: \"N\", \"Shift+N\", \"Ctrl+1\", \"PgUp\"). "
      "Each key may belong to one action only.",
      QString::fromStdString(keymap_.toJson()), QString::fromStdString(ReadingKeymap().toJson()),
      [this](const std::string& json) {
        ReadingKeymap k;
        k.applyJson(json, qtKeyNormaliser);
        QDir().mkpath(configFolder_);
        std::ofstream out(keymapPath().toStdString(), std::ios::trunc);
        out << k.toJson();
        if (!out)
          throw outputError(keymapPath().toStdString() +
                            ": cannot be written; check the folder's permissions");
        keymap_ = k;
        applyKeys();
      });
  d.exec();
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

void ReadingActions::page(int direction) {
  const auto v = models_.document.volume();
  if (!v) return;
  SliceView& s = focusedSlice();
  const int axis = s.axes().nAxis;
  const int n = pageSlices(models_.crosshair.slab(s.orientation()).thicknessMm, v->spacingMm[axis]);
  models_.crosshair.scrollView(s.axes(), direction * n);
}

void ReadingActions::status(const QString& text) { window_.statusBar()->showMessage(text, 8000); }

}  // namespace voxray::ui
