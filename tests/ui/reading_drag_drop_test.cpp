// A series dragged from the study browser and dropped on a view, a compare column or a
// series cell.
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

// Issue 37: a series row dragged from the study browser onto a view opens there. On a cell
// of the grid other than the main one it shows beside (compare's right column, as Reading →
// Show series in this view); on compare's left column it becomes the main document and on
// its right column compare's series, the other column kept each time. The mime data is the
// browser's own (its rows' drag); the drop goes to the view as Qt delivers it.
void ReadingTest::seriesDroppedFromTheBrowserOpensInThatView() {
#ifndef VOXRAY_HAS_STUDYDB
  QSKIP("built without the study database");
#else
  window_->resize(1800, 1000);
  const fs::path study = freshDir("drop-series");
  const auto uids =
      writeStudy(study, {{"T2 LIKE 10MM", 3010, true, 100}, {"EVEN 10MM", 3020, false, 200}});
  QCOMPARE(uids.size(), size_t(2));
  const std::string db = freshDir("drop-series-db").string();
  const QByteArray before = qgetenv("VOXRAY_STUDY_DB");
  qputenv("VOXRAY_STUDY_DB", QByteArray::fromStdString(db));  // never the user's database
  StudyDb(db).import({study.string()});
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(study.string(), {});
  QVERIFY(shown.wait(120000));
  const auto brain = fixture_.models->document.volume();
  QCOMPARE(brain->study.seriesDescription, std::string("STD BRAIN 5MM"));
  QCOMPARE(brain->dims.z, 28);
  StudyBrowserDialog* b = window_->showStudyBrowser();
  qputenv("VOXRAY_STUDY_DB", before);
  QVERIFY(b);
  b->search();
  QCOMPARE(b->tree()->topLevelItemCount(), 1);
  QTreeWidgetItem* studyItem = b->tree()->topLevelItem(0)->child(0);
  QVERIFY(studyItem);
  b->listSeries(studyItem);
  auto mimeOf = [&](const std::string& uid) {
    for (int i = 0; i < studyItem->childCount(); ++i)
      if (studyItem->child(i)->data(0, Qt::UserRole).toString().toStdString() == uid)
        return std::unique_ptr<QMimeData>(b->dragData(studyItem->child(i)));
    return std::unique_ptr<QMimeData>();
  };
  const auto t2 = mimeOf(uids[0]), even = mimeOf(uids[1]),
             std = mimeOf(brain->study.seriesInstanceUid);
  QVERIFY(t2 && even && std);

  // 1. On a slice view that is not the layout's first cell: T2 beside, the study kept.
  const auto cells = visibleCells(reading_->reading());
  QVERIFY(cells.size() > 1);
  const GridView second = cells[1].view;
  QWidget* cell = second == GridView::Volume3d ? static_cast<QWidget*>(&window_->volumeView())
                                               : &window_->sliceView(int(second) - 1);
  QVERIFY(dropOn(cell, t2.get()));
  QTRY_VERIFY_WITH_TIMEOUT(window_->compareView() && window_->compareView()->hasPrior() &&
                               window_->compareView()->isVisible(),
                           60000);
  CompareView* c = window_->compareView();
  auto prior = [&] { return c->prior().document.volume(); };
  QCOMPARE(prior()->study.seriesInstanceUid, uids[0]);
  QCOMPARE(prior()->dims.z, 14);
  QCOMPARE(firstVoxelHu(*prior()), derivedFirstVoxelHu(*brain, *prior(), 100));
  QCOMPARE(fixture_.models->document.volume(), brain);  // the left column kept
  const auto placed =
      std::find_if(reading_->reading().placed.begin(), reading_->reading().placed.end(),
                   [&](const PlacedView& p) { return p.view == second; });
  QVERIFY(placed != reading_->reading().placed.end());
  QCOMPARE(placed->uid, uids[0]);  // a session keeps it

  // 2. On compare's left column: the main document is EVEN now; the right column kept.
  QVERIFY(dropOn(&c->fixedView(), even.get()));
  QVERIFY(shown.wait(120000));
  const auto left = fixture_.models->document.volume();
  QCOMPARE(left->study.seriesInstanceUid, uids[1]);
  QCOMPARE(left->dims.z, 14);
  QCOMPARE(firstVoxelHu(*left), derivedFirstVoxelHu(*brain, *left, 200));
  QVERIFY(firstVoxelHu(*left) != firstVoxelHu(*prior()));
  QTRY_VERIFY(c->isVisible());
  QCOMPARE(prior()->study.seriesInstanceUid, uids[0]);

  // 3. On compare's right column: STD BRAIN there; the left column (EVEN) kept.
  QVERIFY(dropOn(&c->movingView(), std.get()));
  QTRY_VERIFY_WITH_TIMEOUT(
      prior() && prior()->study.seriesInstanceUid == brain->study.seriesInstanceUid, 60000);
  QCOMPARE(prior()->dims.z, 28);
  QCOMPARE(firstVoxelHu(*prior()), firstVoxelHu(*brain));
  QCOMPARE(fixture_.models->document.volume(), left);
  QVERIFY(c->isVisible());
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
#endif
}

}  // namespace voxray::ui::test
