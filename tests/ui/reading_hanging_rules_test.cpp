// Hanging protocols: a matching rule's window and layout when a study opens, the rule
// editor's validation, and a rule's series placement (a missing series left empty, two
// series side by side linked in patient z).
#include <filesystem>

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

void ReadingTest::matchingRuleAppliesItsWindowAndLayout() {
  useRules("rules", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "chest", "match": {"series-description": "chest"}, "window": "Lung"},
      {"name": "head bone", "match": {"modality": "CT", "body-part": "brain",
                                      "series-description": "/brain\\s+5mm/"},
       "layout": "1x2", "window": "Bone", "preset": "CT-Skin"}]})");
  QVERIFY(errors_.isEmpty());
  QSignalSpy applied(reading_, &ReadingActions::protocolApplied);
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(kBrain, {});
  QVERIFY(shown.wait(120000));
  QCOMPARE(applied.size(), 1);
  QCOMPARE(applied[0][0].toString(), QString("head bone"));
  QCOMPARE(fixture_.models->windowLevel.value().width, 1800.0);  // Bone, not the DICOM window
  QCOMPARE(fixture_.models->windowLevel.value().level, 400.0);
  QCOMPARE(fixture_.models->windowLevel.source(), std::string("hanging protocol: head bone"));
  QCOMPARE(reading_->layout(), ViewLayout::OneByTwo);
  QVERIFY(!window_->sliceView(1).isVisible());
  QCOMPARE(fixture_.models->render.params().preset, std::string("CT-Skin"));
}

// Reading → Hanging protocols…: a bad text is kept in the editor with the field named; a
// good one is saved in the config folder and used.
void ReadingTest::ruleEditorNamesTheFieldAndSavesWhatValidates() {
  JsonTextDialog d(window_, "Hanging protocols", "", "", "",
                   [this](const std::string& json) { reading_->setProtocolsJson(json); });
  d.editor()->setPlainText(
      R"({"voxray-hanging-protocols": 1, "rules": [{"name": "x", "layout": "2x3"}]})");
  QVERIFY(!d.save());
  QVERIFY2(d.message()->text().contains("rules[0].layout: '2x3' is not a layout"),
           qPrintable(d.message()->text()));
  QVERIFY(!fs::exists(reading_->hangingProtocolsPath().toStdString()));
  d.editor()->setPlainText(
      R"({"voxray-hanging-protocols": 1, "rules": [{"name": "x", "window": "Liver"}]})");
  QVERIFY(d.save());
  QVERIFY(d.message()->text().isEmpty());
  QCOMPARE(reading_->protocols().rules.size(), size_t(1));
  QCOMPARE(reading_->protocols().rules[0].window, std::string("Liver"));
  QCOMPARE(loadHangingProtocols(reading_->hangingProtocolsPath().toStdString()).rules[0].name,
           std::string("x"));
}

// A rule's series placement: the view whose series the study lacks is left empty with a
// note, and a session keeps the placement.
void ReadingTest::ruleSeriesPlacementLeavesAMissingSeriesEmptyAndTheSessionKeepsIt() {
  window_->resize(1800, 1000);
  useRules("placement", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "head", "match": {"modality": "CT"}, "layout": "2x2",
       "series": {"axial": "brain", "coronal": 1, "sagittal": "STIR"}}]})");
  QVERIFY(errors_.isEmpty());
  openBrain();
  QCOMPARE(reading_->layout(), ViewLayout::TwoByTwo);
  const ReadingLayout& r = reading_->reading();
  QCOMPARE(r.placed.size(), size_t(3));
  for (const PlacedView& p : r.placed) {
    if (p.view == GridView::Sagittal) {
      QVERIFY(p.series.empty());
      QCOMPARE(p.note, std::string("no series of this study matches 'STIR' (rule 'head'); the "
                                   "view is left empty"));
    } else {
      QCOMPARE(p.description, std::string("STD BRAIN 5MM"));  // the study's one volume series
      QVERIFY(!p.series.empty());
    }
  }
  QTRY_VERIFY(window_->sliceView(0).isVisible() && window_->sliceView(1).isVisible());
  QVERIFY(!window_->sliceView(2).isVisible());  // empty: no STIR series
  QVERIFY(window_->volumeView().isVisible());   // the rule names no series for it
  QVERIFY2(window_->statusBar()->currentMessage().contains("sagittal: no series of this study "
                                                           "matches 'STIR'"),
           qPrintable(window_->statusBar()->currentMessage()));
  const std::string file = (freshDir("placement-session") / "s.json").string();
  window_->sessions().tell = [this](const QString& t, const QString& m) {
    errors_ << t + ": " + m;
  };
  QVERIFY(window_->sessions().saveTo(QString::fromStdString(file)));
  reading_->setLayout(ViewLayout::One);  // the user's choice: every view shows the volume
  QVERIFY(reading_->reading().placed.empty());
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->sessions().openFile(file);
  QVERIFY(shown.wait(120000));
  QCOMPARE(reading_->reading(), r);
  QTRY_VERIFY(window_->sliceView(1).isVisible());
  QVERIFY(!window_->sliceView(2).isVisible());
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
}

// The classic T1 | T2 hanging: a rule placing two series of one study in one layout shows
// both, side by side (compare's two columns, each with its own volume), linked in patient
// coordinates; the session keeps the placement and opens both again; a session whose second
// series was removed since opens the rest and says which view is left empty.
void ReadingTest::ruleShowsTwoSeriesSideBySideLinkedInPatientZ() {
  window_->resize(1800, 1000);
  const fs::path study = freshDir("two-series");
  const std::string t2Uid = writeTwoSeriesStudy(study);
  QVERIFY(!t2Uid.empty());
  useRules("two-series-config", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "pair", "match": {"modality": "CT"}, "layout": "1x2",
       "series": {"axial": "STD BRAIN", "3d": "T2 LIKE"}}]})");
  QVERIFY(errors_.isEmpty());
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(study.string(), {});
  QVERIFY(shown.wait(120000));
  // Both series placed, neither left empty.
  const ReadingLayout r = reading_->reading();
  QCOMPARE(r.layout, ViewLayout::OneByTwo);
  QCOMPARE(r.placed.size(), size_t(2));
  QVERIFY(emptyViewNotes(r).empty());
  const auto placed3d = std::find_if(r.placed.begin(), r.placed.end(), [](const PlacedView& p) {
    return p.view == GridView::Volume3d;
  });
  QCOMPARE(placed3d->description, std::string("T2 LIKE 10MM"));
  QCOMPARE(placed3d->uid, t2Uid);
  // The second series opens beside the first: two columns, each its own volume.
  QTRY_VERIFY_WITH_TIMEOUT(window_->compareView() && window_->compareView()->hasPrior(), 60000);
  CompareView* c = window_->compareView();
  QTRY_VERIFY(c->isVisible() && c->fixedView().isVisible() && c->movingView().isVisible());
  const Volume& left = *fixture_.models->document.volume();
  const Volume& right = *c->prior().document.volume();
  QCOMPARE(left.study.seriesDescription, std::string("STD BRAIN 5MM"));
  QCOMPARE(right.study.seriesInstanceUid, t2Uid);
  QCOMPARE(left.dims.z, 28);
  QCOMPARE(right.dims.z, 14);
  QVERIFY(std::abs(right.spacingMm.z - 2.0 * left.spacingMm.z) < 1e-3);  // 10 mm and 5 mm
  QVERIFY(c->comparison().sameFrameOfReference() && c->comparison().linked());
  // Scrolling the left column moves the right one to the same patient z, within half of
  // its 10 mm slices (it rounds to its own slice centres).
  CrosshairModel& lc = fixture_.models->crosshair;
  double lastZ = voxelToPatientMm(left, lc.centre()).z;
  for (int notches : {3, -1, 5, -7, 2}) {
    wheel(&c->fixedView(), notches);
    const double z = voxelToPatientMm(left, lc.centre()).z;
    QVERIFY2(std::abs(std::abs(z - lastZ) - std::abs(notches) * left.spacingMm.z) < 1e-6,
             qPrintable(QString("moved %1 mm for %2 notches").arg(z - lastZ).arg(notches)));
    lastZ = z;
    const double rz = voxelToPatientMm(right, c->prior().crosshair.centre()).z;
    QVERIFY2(std::abs(rz - z) <= 0.5 * right.spacingMm.z + 1e-6,
             qPrintable(QString("right z %1 vs left z %2").arg(rz).arg(z)));
  }

  // The session keeps both series and opens them again.
  const std::string file = (freshDir("two-series-session") / "s.json").string();
  window_->sessions().tell = [this](const QString& t, const QString& m) {
    errors_ << t + ": " + m;
  };
  QVERIFY(window_->sessions().saveTo(QString::fromStdString(file)));
  reading_->setLayout(ViewLayout::One);  // the user's choice: the second column goes
  QTRY_VERIFY(!c->isVisible());
  window_->sessions().openFile(file);
  QVERIFY(shown.wait(120000));
  QCOMPARE(reading_->reading(), r);
  QTRY_VERIFY_WITH_TIMEOUT(
      window_->compareView()->isVisible() && window_->compareView()->prior().document.volume() &&
          window_->compareView()->prior().document.volume()->study.seriesInstanceUid == t2Uid,
      60000);
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));

  // The second series removed from the study: the session opens the first and names the
  // view left empty.
  for (const auto& e : fs::directory_iterator(study))
    if (e.path().filename().string().rfind("b-", 0) == 0) fs::remove(e.path());
  window_->sessions().openFile(file);
  QVERIFY(shown.wait(120000));
  QTRY_VERIFY(!errors_.isEmpty());
  QVERIFY2(errors_.join('\n').contains("View 3d: its series 'T2 LIKE 10MM' is no longer in the "
                                       "study; the view is left empty"),
           qPrintable(errors_.join('\n')));
  QCOMPARE(fixture_.models->document.volume()->study.seriesDescription,
           std::string("STD BRAIN 5MM"));
  QTRY_VERIFY(!window_->compareView()->isVisible());
  QVERIFY(window_->sliceView(0).isVisible());
  QVERIFY(!fixture_.models->comparison);  // nothing left to open beside it
}

}  // namespace voxray::ui::test
