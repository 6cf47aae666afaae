// More than two series at once: a rule placing four series, each in a cell of its own, and
// Show series in this view.
#include <filesystem>
#include <memory>

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

// Issue 37: a 2x2 rule naming four series puts each in its named cell: the first cell's
// series is the main document, each other one opens in a cell of its own (an axial view of
// that series: its own volume, window and crosshair; in the 3D view's place the series in
// 3D) in its view's place, the crosshairs linked in patient coordinates; a session keeps
// the four and opens them again; a series dropped on a cell opens there; another study
// closes the cells.
void ReadingTest::ruleShowsFourSeriesEachInItsCell() {
  window_->resize(1800, 1000);
  const fs::path study = freshDir("four-series");
  const std::vector<DerivedSeries> derived = {{"T2 LIKE 10MM", 3010, true, 100},
                                              {"EVEN 10MM", 3020, false, 200},
                                              {"ODD PLUS 10MM", 3030, true, 300}};
  const auto uids = writeStudy(study, derived);
  QCOMPARE(uids.size(), size_t(3));
  useRules("four-series-config", R"({"voxray-hanging-protocols": 1, "rules": [
      {"name": "four", "match": {"modality": "CT"}, "layout": "2x2",
       "series": {"axial": "STD BRAIN", "coronal": "T2 LIKE", "sagittal": "EVEN",
                  "3d": "ODD PLUS"}}]})");
  QVERIFY(errors_.isEmpty());
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(study.string(), {});
  QVERIFY(shown.wait(120000));
  const ReadingLayout r = reading_->reading();
  QCOMPARE(r.layout, ViewLayout::TwoByTwo);
  QCOMPARE(r.placed.size(), size_t(4));
  QVERIFY(emptyViewNotes(r).empty());
  const auto brain = fixture_.models->document.volume();
  QCOMPARE(brain->study.seriesDescription, std::string("STD BRAIN 5MM"));
  QCOMPARE(brain->dims.z, 28);
  // The cells in the views the rule names, each with its own series (dims, UID and first
  // voxel's HU: each derived series is shifted by its own HU).
  const GridView views[] = {GridView::Coronal, GridView::Sagittal, GridView::Volume3d};
  const SeriesCells& cells = reading_->seriesCells();
  auto cellWidget = [&](GridView v) -> QWidget* {
    return v == GridView::Volume3d ? static_cast<QWidget*>(reading_->cell3dView())
                                   : reading_->cellView(v);
  };
  auto loaded = [&] {
    for (GridView v : views) {
      const SeriesCell* c = cells.cell(v);
      if (!c || c->document.empty()) return false;
    }
    return cells.cells().size() == 3;
  };
  QTRY_VERIFY_WITH_TIMEOUT(loaded(), 120000);
  for (size_t i = 0; i < 3; ++i) {
    const SeriesCell& c = *cells.cell(views[i]);
    const Volume& v = *c.document.volume();
    QCOMPARE(v.study.seriesInstanceUid, uids[i]);
    QCOMPARE(v.dims.z, 14);
    QCOMPARE(firstVoxelHu(v), derivedFirstVoxelHu(*brain, v, derived[i].huShift));
    QVERIFY(c.comparison.sameFrameOfReference() && c.comparison.linked());
    QWidget* view = cellWidget(views[i]);
    QVERIFY(view);
    QTRY_VERIFY(view->isVisible());
  }
  QCOMPARE(fixture_.models->document.volume(), brain);  // the main document kept
  // Each in its named place (2x2: axial, coronal / sagittal, 3D), the grid's own views of
  // those places hidden.
  SliceView& axial = window_->sliceView(0);
  QVERIFY(axial.isVisible());
  QVERIFY(!window_->sliceView(1).isVisible() && !window_->sliceView(2).isVisible() &&
          !window_->volumeView().isVisible());
  SliceView* coronal = reading_->cellView(GridView::Coronal);
  SliceView* sagittal = reading_->cellView(GridView::Sagittal);
  VolumeView* threeD = reading_->cell3dView();  // the 3D view's place: its series in 3D
  QVERIFY(threeD && !reading_->cellView(GridView::Volume3d));
  // (Each cell's view sits below its series' name: its top is below the axial view's.)
  auto at = [&](QWidget* w) { return w->mapTo(window_, QPoint(0, 0)); };
  QTRY_VERIFY(at(coronal).x() > at(&axial).x() && at(coronal).y() >= at(&axial).y() &&
              at(coronal).y() < at(&axial).y() + axial.height() / 4);
  QVERIFY(at(sagittal).x() == at(&axial).x() && at(sagittal).y() > at(&axial).y() + axial.height());
  QVERIFY(at(threeD).x() == at(coronal).x() && at(threeD).y() == at(sagittal).y());

  // Scrolling the main cell moves every other to the same patient z within half of its
  // 10 mm slices (each rounds to its own slice centres); scrolling a cell moves the main
  // one within half of its 5 mm slices, and the others with it.
  CrosshairModel& mc = fixture_.models->crosshair;
  auto mainZ = [&] { return voxelToPatientMm(*brain, mc.centre()).z; };
  auto cellZ = [&](GridView v) {
    const SeriesCell& c = *cells.cell(v);
    return voxelToPatientMm(*c.document.volume(), c.crosshair.centre()).z;
  };
  auto othersFollow = [&](const QString& what) {
    for (GridView v : views)
      if (std::abs(cellZ(v) - mainZ()) > 0.5 * 10.0 + 1e-6)
        return what + QString(": %1 at z %2, main at %3")
                          .arg(QString::fromStdString(gridViewName(v)))
                          .arg(cellZ(v))
                          .arg(mainZ());
    return QString();
  };
  double lastZ = mainZ();
  for (int notches : {3, -1, 5, -7, 2}) {
    wheel(&axial, notches);
    QVERIFY2(std::abs(std::abs(mainZ() - lastZ) - std::abs(notches) * brain->spacingMm.z) < 1e-6,
             qPrintable(QString("moved %1 mm for %2 notches").arg(mainZ() - lastZ).arg(notches)));
    lastZ = mainZ();
    const QString off = othersFollow("main scrolled");
    QVERIFY2(off.isEmpty(), qPrintable(off));
  }
  for (int notches : {2, -3}) {
    const double before = cellZ(GridView::Coronal);
    wheel(coronal, notches);
    QVERIFY2(
        std::abs(std::abs(cellZ(GridView::Coronal) - before) - 10.0 * std::abs(notches)) < 1e-6,
        qPrintable(QString("the cell moved %1 mm").arg(cellZ(GridView::Coronal) - before)));
    QVERIFY2(
        std::abs(mainZ() - cellZ(GridView::Coronal)) <= 0.5 * brain->spacingMm.z + 1e-6,
        qPrintable(QString("main z %1, cell z %2").arg(mainZ()).arg(cellZ(GridView::Coronal))));
    const QString off = othersFollow("a cell scrolled");
    QVERIFY2(off.isEmpty(), qPrintable(off));
  }

  // The 3D cell renders its series through its own render thread, its camera the main
  // one's (one Frame of Reference): the main camera turned, the cell's frame follows.
  {
    QSignalSpy frames(reading_->cell3dScheduler(), &RenderScheduler::frameReady);
    fixture_.models->render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 40.0; });
    const SeriesCell& c = *cells.cell(GridView::Volume3d);
    QCOMPARE(c.render.params().camera.azimuthDeg, 40.0);
    bool full = false;
    for (int tries = 0; tries < 600 && !full; ++tries) {
      if (frames.isEmpty()) frames.wait(100);
      while (!frames.isEmpty())
        full = !frames.takeFirst().at(0).value<std::shared_ptr<const Frame>>()->interactive;
    }
    QVERIFY2(full, "the 3D cell rendered no full frame within 60 s");
    QCoreApplication::processEvents();
    const QImage f = threeD->lastFrame();
    QVERIFY(!f.isNull());
    // The head in the frame: more than a tenth of its pixels differ from the corner's
    // background (the head fills about half of a framed view).
    int head = 0;
    for (int y = 0; y < f.height(); ++y)
      for (int x = 0; x < f.width(); ++x) head += f.pixel(x, y) != f.pixel(0, 0);
    QVERIFY2(head > f.width() * f.height() / 10, qPrintable(QString("%1 pixels").arg(head)));
  }

  // README's docs/images/reading-four-series.png with VOXRAY_CELLS_SHOT=PATH (under xvfb-run
  // -s "-screen 0 1920x1080x24"): the four series on slice 14 of the head CT.
  if (const QString shot = qEnvironmentVariable("VOXRAY_CELLS_SHOT"); !shot.isEmpty()) {
    window_->resize(1900, 1040);
    mc.setVoxel({256, 256, 14});
    QTest::qWait(1000);
    QVERIFY(window_->grab().save(shot));
  }

  // The session keeps the four and opens them again.
  const std::string file = (freshDir("four-series-session") / "s.json").string();
  window_->sessions().tell = [this](const QString& t, const QString& m) {
    errors_ << t + ": " + m;
  };
  QVERIFY(window_->sessions().saveTo(QString::fromStdString(file)));
  reading_->setLayout(ViewLayout::One);  // the user's choice: the cells close
  QVERIFY(cells.empty());
  QVERIFY(!reading_->cellView(GridView::Coronal));
  window_->sessions().openFile(file);
  QVERIFY(shown.wait(120000));
  QCOMPARE(reading_->reading(), r);
  QTRY_VERIFY_WITH_TIMEOUT(loaded(), 120000);
  QCOMPARE(fixture_.models->document.volume()->study.seriesDescription,
           std::string("STD BRAIN 5MM"));
  for (size_t i = 0; i < 3; ++i) {
    const Volume& v = *cells.cell(views[i])->document.volume();
    QCOMPARE(v.study.seriesInstanceUid, uids[i]);
    QCOMPARE(firstVoxelHu(v), derivedFirstVoxelHu(*brain, v, derived[i].huShift));
    QTRY_VERIFY(cellWidget(views[i]) && cellWidget(views[i])->isVisible());
  }
  QVERIFY(!window_->compareView() || !window_->compareView()->isVisible());

  // T2 dragged from the study browser onto the sagittal cell: it shows T2 there (its HU),
  // the other cells kept as they are; the placement (a session) says so.
  const SeriesCell* coronalCell = cells.cell(GridView::Coronal);
  const std::unique_ptr<QMimeData> t2(seriesMimeData(
      {QString::fromStdString(study.string()), "", QString::fromStdString(uids[0]), "T2"}));
  QVERIFY(dropOn(reading_->cellView(GridView::Sagittal), t2.get()));
  auto sagittalIsT2 = [&] {
    const SeriesCell* c = cells.cell(GridView::Sagittal);
    return c && !c->document.empty() && c->document.volume()->study.seriesInstanceUid == uids[0];
  };
  QTRY_VERIFY_WITH_TIMEOUT(sagittalIsT2(), 120000);
  const Volume& t2There = *cells.cell(GridView::Sagittal)->document.volume();
  QCOMPARE(firstVoxelHu(t2There), derivedFirstVoxelHu(*brain, t2There, derived[0].huShift));
  QCOMPARE(cells.cell(GridView::Coronal), coronalCell);
  QCOMPARE(cells.cell(GridView::Volume3d)->document.volume()->study.seriesInstanceUid, uids[2]);
  const auto& placedNow = reading_->reading().placed;
  QCOMPARE(std::find_if(placedNow.begin(), placedNow.end(),
                        [](const PlacedView& p) { return p.view == GridView::Sagittal; })
               ->uid,
           uids[0]);
  QTRY_VERIFY(reading_->cellView(GridView::Sagittal)->isVisible());

  // Another study (hung by the default rules: CT head, MPR+3D, no series placed): its cells
  // close and the grid's own views are back.
  reading_->setConfigFolder(QString::fromStdString(freshDir("four-series-defaults").string()));
  window_->open(kBrain, {});
  QVERIFY(shown.wait(120000));
  QVERIFY(cells.empty());
  QVERIFY(!reading_->cellView(GridView::Coronal));
  QVERIFY(reading_->reading().placed.empty());
  QTRY_VERIFY(window_->sliceView(1).isVisible() && window_->sliceView(2).isVisible());
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
}

// Issue 37: "Show series in this view" (Reading menu) puts another series of the study in
// the focused view: it opens beside the open one.
void ReadingTest::showSeriesInThisViewOpensItBeside() {
  const fs::path study = freshDir("show-series");
  const std::string t2Uid = writeTwoSeriesStudy(study);
  QVERIFY(!t2Uid.empty());
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(study.string(), {});
  QVERIFY(shown.wait(120000));
  QMenu* menu = window_->findChild<QMenu*>("readingShowSeries");
  QVERIFY(menu);
  emit menu->aboutToShow();
  QAction* t2 = nullptr;
  for (QAction* a : menu->actions())
    if (a->text() == "T2 LIKE 10MM") t2 = a;
  QVERIFY2(t2, "the menu lists the study's second series");
  t2->trigger();  // the axial view focused (init)
  QTRY_VERIFY_WITH_TIMEOUT(window_->compareView() && window_->compareView()->hasPrior(), 60000);
  QCOMPARE(window_->compareView()->prior().document.volume()->study.seriesInstanceUid, t2Uid);
  const auto& placed = reading_->reading().placed;
  const auto axial = std::find_if(placed.begin(), placed.end(),
                                  [](const PlacedView& p) { return p.view == GridView::Axial; });
  QVERIFY(axial != placed.end());
  QCOMPARE(axial->uid, t2Uid);
  QVERIFY(errors_.isEmpty());
}

}  // namespace voxray::ui::test
