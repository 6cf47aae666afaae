#include "reading_actions.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QKeySequence>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QTreeWidget>

#include "gui_message.h"
#include "json_text_dialog.h"
#include "load_controller.h"
#include "main_window.h"
#include "session_actions.h"
#include "slice_view.h"
#include "study_attributes.h"
#include "study_browser_dialog.h"
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
    : QObject(&window), window_(window), models_(models) {
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
    if (pendingPlacement_) {  // the series a rule placed is shown now
      ReadingLayout r = *pendingPlacement_;
      pendingPlacement_.reset();
      const std::string shown = shownSeries(r.layout, r.placed).value_or("");
      r.placed = keepShown(r.placed, shown);
      setReading(r);
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
  menu->addAction("&Hanging protocols…", this, [this] { showHangingProtocolEditor(); })
      ->setObjectName("readingHangingProtocols");
  menu->addAction("&Keymap…", this, [this] { showKeymapEditor(); })->setObjectName("readingKeymap");
}

void ReadingActions::setLayout(ViewLayout l) {
  QSettings().setValue(kLastLayoutKey, QString::fromStdString(layoutName(l)));
  pendingPlacement_.reset();
  pendingRule_.reset();
  setReading(ReadingLayout{l, {}});
}

void ReadingActions::setReading(const ReadingLayout& r) {
  reading_ = r;
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
  for (const auto& s : volumes) study.push_back({s.selector, s.description});
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
  placed.placed = keepShown(placed.placed, current);
  setReading(placed);
  return false;
#else
  return false;
#endif
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
                   "description or by place (1, 2, …); the views show one series at a time.",
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
