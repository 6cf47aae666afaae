// Reading → the menu and its keys: the keymap and its editor, the user's config files, layouts
// and the views' focus, paging. Hanging protocols: reading_actions_hanging.cpp; the study's
// series: reading_actions_series.cpp; series cells: reading_actions_cells.cpp.
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

GridView ReadingActions::focusedGridView() const {
  return std::array{GridView::Axial, GridView::Coronal, GridView::Sagittal}[size_t(focusedSlice_)];
}

QString ReadingActions::emptyViewsText() const {
  QStringList notes;
  for (const std::string& n : emptyViewNotes(reading_)) notes << QString::fromStdString(n);
  return notes.isEmpty() ? QString() : "Views left empty: " + notes.join("  ·  ");
}

SliceView& ReadingActions::focusedSlice() const { return window_.sliceView(focusedSlice_); }

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
