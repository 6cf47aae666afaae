// The reading tests' fixture: a window on the head phantom for each test, its own config
// folder, and the helpers that write the studies the tests open (reading_test.h).
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QWheelEvent>

#include <dcmtk/dcmdata/dctk.h>
#include <nlohmann/json.hpp>

#include "annotation_model.h"
#include "compare_view.h"
#include "help_dialogs.h"
#include "json_text_dialog.h"
#include "pacs_node_config.h"
#include "pacs_node_dialog.h"
#include "reading_actions.h"
#include "reading_test.h"
#include "render_scheduler.h"
#include "results_actions.h"
#include "segment_panel.h"
#include "series_drag.h"
#include "session_actions.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "study_browser_dialog.h"
#include "volume_view.h"
#include "voxray/io/phantom_series.h"
#ifdef VOXRAY_HAS_STUDYDB
#include "voxray/studydb/study_db.h"
#endif

namespace voxray::ui::test {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path p = fs::path(VOXRAY_TEST_TMP) / ("reading-" + std::to_string(getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

namespace {

// Every value of TAG anywhere in ITEM (sequences included), as DCMTK reads it.
void collect(DcmItem& item, const DcmTagKey& tag, std::vector<std::string>& out) {
  for (unsigned long i = 0; i < item.card(); ++i) {
    DcmElement* e = item.getElement(i);
    if (e->getTag() == tag) {
      OFString v;
      if (e->getOFStringArray(v).good()) out.emplace_back(v.c_str());
    }
    if (auto* seq = dynamic_cast<DcmSequenceOfItems*>(e))
      for (unsigned long k = 0; k < seq->card(); ++k) collect(*seq->getItem(k), tag, out);
  }
}

}  // namespace

std::vector<std::string> valuesIn(const fs::path& file, const DcmTagKey& tag) {
  DcmFileFormat f;
  if (f.loadFile(file.c_str()).bad()) return {};
  std::vector<std::string> out;
  collect(*f.getDataset(), tag, out);
  return out;
}

std::string writeTwoSeriesStudy(const fs::path& folder) {
  char uid[100];
  const std::string seriesUid = dcmGenerateUniqueIdentifier(uid, SITE_SERIES_UID_ROOT);
  int written = 0;
  for (const auto& e : fs::directory_iterator(kBrain)) {
    DcmFileFormat f;
    if (!e.is_regular_file() || f.loadFile(e.path().c_str()).bad()) continue;
    fs::copy_file(e.path(), folder / ("a-" + e.path().filename().string()));
    DcmDataset& d = *f.getDataset();
    Sint32 instance = 0;
    if (d.findAndGetSint32(DCM_InstanceNumber, instance).bad() || instance % 2 == 0) continue;
    d.putAndInsertString(DCM_SeriesInstanceUID, seriesUid.c_str());
    d.putAndInsertString(DCM_SeriesDescription, "T2 LIKE 10MM");
    d.putAndInsertString(DCM_SeriesNumber, "3010");
    d.putAndInsertString(DCM_SOPInstanceUID,
                         dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT));
    if (f.saveFile((folder / ("b-" + e.path().filename().string())).c_str(), EXS_Unknown,
                   EET_UndefinedLength, EGL_recalcGL, EPD_noChange, 0, 0, EWM_updateMeta)
            .bad())
      return "";
    ++written;
  }
  return written == 14 ? seriesUid : "";
}

std::vector<std::string> writeStudy(const fs::path& folder,
                                    const std::vector<DerivedSeries>& derived) {
  char uid[100];
  std::vector<std::string> uids;
  for (size_t n = 0; n < derived.size(); ++n)
    uids.push_back(dcmGenerateUniqueIdentifier(uid, SITE_SERIES_UID_ROOT));
  std::vector<int> written(derived.size(), 0);
  for (const auto& e : fs::directory_iterator(kBrain)) {
    DcmFileFormat f;
    if (!e.is_regular_file() || f.loadFile(e.path().c_str()).bad()) continue;
    fs::copy_file(e.path(), folder / ("a-" + e.path().filename().string()));
    for (size_t n = 0; n < derived.size(); ++n) {
      DcmFileFormat g(f);
      DcmDataset& d = *g.getDataset();
      Sint32 instance = 0;
      Float64 intercept = 0;
      if (d.findAndGetSint32(DCM_InstanceNumber, instance).bad() ||
          (instance % 2 == 1) != derived[n].odd ||
          d.findAndGetFloat64(DCM_RescaleIntercept, intercept).bad())
        continue;
      d.putAndInsertString(DCM_SeriesInstanceUID, uids[n].c_str());
      d.putAndInsertString(DCM_SeriesDescription, derived[n].description.c_str());
      d.putAndInsertString(DCM_SeriesNumber, std::to_string(derived[n].number).c_str());
      d.putAndInsertString(DCM_RescaleIntercept,
                           std::to_string(int(intercept) + derived[n].huShift).c_str());
      d.putAndInsertString(DCM_SOPInstanceUID,
                           dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT));
      std::string name = "d";  // d0-FILE, d1-FILE, ... (appended: GCC 12 warns on a + chain)
      name += std::to_string(n);
      name += '-';
      name += e.path().filename().string();
      const fs::path out = folder / name;
      if (g.saveFile(out.c_str(), EXS_Unknown, EET_UndefinedLength, EGL_recalcGL, EPD_noChange, 0,
                     0, EWM_updateMeta)
              .bad())
        return {};
      ++written[n];
    }
  }
  for (int w : written)
    if (w != 14) return {};
  return uids;
}

double firstVoxelHu(const Volume& v) { return v.toPhysical(v.at(0, 0, 0)); }

double derivedFirstVoxelHu(const Volume& brain, const Volume& v, int shift) {
  const glm::dvec3 p = voxelToPatientMm(v, glm::dvec3(0.0));
  const double along = glm::dot(p - brain.originMm, brain.direction[2]) / brain.spacingMm.z;
  return brain.toPhysical(brain.at(0, 0, int(std::lround(along)))) + shift;
}

bool dropOn(QWidget* w, const QMimeData* m) {
  const QPoint at(w->width() / 2, w->height() / 2);
  QDragEnterEvent enter(at, Qt::CopyAction, m, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(w, &enter);
  QDropEvent drop(QPointF(at), Qt::CopyAction, m, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(w, &drop);
  return enter.isAccepted() && drop.isAccepted();
}

void wheel(QWidget* w, int notches) {
  const QPointF at(w->width() / 2.0, w->height() / 2.0);
  QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &e);
}

void ReadingTest::init() {
  // Each test starts in the default layout, whatever a test before chose (remembered).
  QSettings().remove("reading/lastLayout");
  QVERIFY(fixture_.start());
  window_ = fixture_.window.get();
  window_->setErrorSink(
      [this](const QString& title, const QString& m) { errors_ << title + ": " + m; });
  errors_.clear();
  reading_ = window_->findChild<ReadingActions*>();
  results_ = window_->findChild<ResultsActions*>();
  QVERIFY(reading_ && results_);
  // Each test's own config folder: no user file, the embedded defaults.
  reading_->setConfigFolder(QString::fromStdString(freshDir("config").string()));
  window_->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(window_));
  window_->sliceView(0).setFocus();
  QTRY_VERIFY(window_->sliceView(0).hasFocus());
}

void ReadingTest::cleanup() { fixture_.stop(); }

void ReadingTest::useRules(const std::string& name, const char* rules) {
  const fs::path dir = freshDir(name);
  std::ofstream(dir / "hanging-protocols.json") << rules;
  reading_->setConfigFolder(QString::fromStdString(dir.string()));
}

void ReadingTest::openBrain() {
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(kBrain, {});
  QVERIFY(shown.wait(120000));
}

void ReadingTest::focusView(QWidget& view) {
  window_->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(window_));
  view.setFocus();
  QTRY_VERIFY(view.hasFocus());
}

void ReadingTest::pollModal(std::function<bool(QWidget*)> match, std::function<void(QWidget*)> fn) {
  auto* timer = new QTimer(this);
  timer->setInterval(20);
  connect(timer, &QTimer::timeout, this, [timer, match, fn] {
    QWidget* w = QApplication::activeModalWidget();
    if (!w || !match(w)) return;
    timer->stop();
    timer->deleteLater();
    fn(w);
  });
  timer->start();
}

}  // namespace voxray::ui::test

QTEST_MAIN(voxray::ui::test::ReadingTest)
