// The reading keys (layouts on Ctrl+1…6, W/L presets on 1–6, pages, tools, next/previous
// series), the keymap file and its validation, and the layout a session and the next start
// keep; the README's reading figure.
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

void ReadingTest::layoutKeysChangeTheGrid() {
  window_->resize(1800, 1000);  // room for the views' minimum widths in every layout
  SliceView& axial = window_->sliceView(0);
  QWidget& volume = window_->volumeView();
  QTest::keyClick(&axial, Qt::Key_1, Qt::ControlModifier);  // 1x1: the axial view alone
  QCOMPARE(reading_->layout(), ViewLayout::One);
  QVERIFY(axial.isVisible());
  QVERIFY(!volume.isVisible());
  QVERIFY(!window_->sliceView(1).isVisible());
  // It takes the whole grid (less the layout's zero margins).
  QTRY_COMPARE(axial.width(), window_->grid().width());
  QTest::keyClick(&axial, Qt::Key_2, Qt::ControlModifier);  // 1x2: axial beside 3D
  QVERIFY(volume.isVisible() && axial.isVisible() && !window_->sliceView(2).isVisible());
  QTRY_VERIFY2(std::abs(axial.width() - volume.width()) <= 2,
               qPrintable(QString("%1 %2").arg(axial.width()).arg(volume.width())));
  QTRY_VERIFY(axial.x() < volume.x());
  QTest::keyClick(&axial, Qt::Key_4, Qt::ControlModifier);  // 1+3: axial twice as wide
  for (int i = 0; i < 3; ++i) QVERIFY(window_->sliceView(i).isVisible());
  QTRY_VERIFY(axial.height() > 2 * window_->sliceView(1).height());
  QTest::keyClick(&axial, Qt::Key_6, Qt::ControlModifier);  // 3D only
  QVERIFY(volume.isVisible() && !axial.isVisible());
  volume.setFocus();
  QTest::keyClick(&volume, Qt::Key_5, Qt::ControlModifier);  // back to MPR+3D
  QCOMPARE(reading_->layout(), ViewLayout::MprPlus3d);
  for (int i = 0; i < 3; ++i) QVERIFY(window_->sliceView(i).isVisible());
  QVERIFY(volume.isVisible());
  QTRY_VERIFY(volume.x() < axial.x());  // 3D top left again
}

void ReadingTest::numberKeysSetTheWindowPresets() {
  SliceView& axial = window_->sliceView(0);
  const std::pair<Qt::Key, WindowLevel> expected[] = {{Qt::Key_1, {80, 40}},      // Brain
                                                      {Qt::Key_3, {1500, -600}},  // Lung
                                                      {Qt::Key_5, {400, 50}},     // Abdomen
                                                      {Qt::Key_6, {1800, 400}}};  // Bone
  for (const auto& [key, wl] : expected) {
    QTest::keyClick(&axial, key);
    QCOMPARE(fixture_.models->windowLevel.value().width, wl.width);
    QCOMPARE(fixture_.models->windowLevel.value().level, wl.level);
  }
}

void ReadingTest::pageKeysMoveByTenOrTheSlab() {
  SliceView& axial = window_->sliceView(0);
  CrosshairModel& c = fixture_.models->crosshair;
  c.setVoxel({32, 32, 20});
  QTest::keyClick(&axial, Qt::Key_PageUp);
  QCOMPARE(c.sliceOf(axial.axes()), 30);
  QTest::keyClick(&axial, Qt::Key_PageDown);
  QTest::keyClick(&axial, Qt::Key_PageDown);
  QCOMPARE(c.sliceOf(axial.axes()), 10);
  // A slab pages by its thickness: the phantom's slices are spacing[2] apart.
  const double spacing = fixture_.models->document.volume()->spacingMm[axial.axes().nAxis];
  Slab slab;
  slab.thicknessMm = 4 * spacing;
  c.setSlab(axial.orientation(), slab);
  QTest::keyClick(&axial, Qt::Key_PageUp);
  QCOMPARE(c.sliceOf(axial.axes()), 14);
}

void ReadingTest::toolKeysPickTheTool() {
  SliceView& axial = window_->sliceView(0);
  MeasurementModel& m = fixture_.models->measurements;
  QTest::keyClick(&axial, Qt::Key_D);
  QCOMPARE(m.tool(), MeasureTool::Distance);
  QTest::keyClick(&axial, Qt::Key_A);
  QCOMPARE(m.tool(), MeasureTool::Angle);
  QTest::keyClick(&axial, Qt::Key_E);
  QCOMPARE(m.tool(), MeasureTool::Ellipse);
  QTest::keyClick(&axial, Qt::Key_P);
  QCOMPARE(m.tool(), MeasureTool::None);
}

void ReadingTest::shortcutsDialogListsTheReadingKeys() {
  const QString html = shortcutsHtml(*window_->menuBar());
  for (const char* expected :
       {"<b>Ctrl+1</b></td><td>Reading → Layout → 1×1 (axial)",
        "<b>Ctrl+5</b></td><td>Reading → Layout → MPR+3D",
        "<b>1</b></td><td>Reading → Window preset → Brain",
        "<b>N</b></td><td>Reading → Next series",
        "<b>Shift+N</b></td><td>Reading → Previous series",
        "<b>PgUp</b></td><td>Reading → Page forward", "<b>D</b></td><td>Reading → Distance",
        "<b>K</b></td><td>Results → Mark key image"})
    QVERIFY2(html.contains(QString::fromUtf8(expected)), expected);
}

void ReadingTest::keymapFileChangesKeysAndADuplicateIsRefused() {
  const fs::path dir = freshDir("keymap");
  std::ofstream(dir / "keymap.json") << R"({"voxray-keymap": 1, "keys": {"tool-distance": "M"}})";
  reading_->setConfigFolder(QString::fromStdString(dir.string()));
  SliceView& axial = window_->sliceView(0);
  QTest::keyClick(&axial, Qt::Key_M);
  QCOMPARE(fixture_.models->measurements.tool(), MeasureTool::Distance);
  // M given twice: refused naming both actions, the defaults stay.
  std::ofstream(dir / "keymap.json", std::ios::trunc)
      << R"({"voxray-keymap": 1, "keys": {"tool-distance": "M", "tool-angle": "m"}})";
  fixture_.models->measurements.setTool(MeasureTool::None);
  reading_->setConfigFolder(QString::fromStdString(dir.string()));
  QTRY_COMPARE(errors_.size(), 1);
  QVERIFY2(errors_[0].contains("(tool-distance)") && errors_[0].contains("(tool-angle)"),
           qPrintable(errors_[0]));
  QCOMPARE(reading_->action("tool-distance")->shortcut(), QKeySequence("D"));
  QTest::keyClick(&axial, Qt::Key_D);
  QCOMPARE(fixture_.models->measurements.tool(), MeasureTool::Distance);
}

void ReadingTest::nextAndPreviousSeriesKeys() {
  // A study folder of two volume series (links to the shared files: nothing copied).
  const fs::path study = freshDir("two-series");
  for (const auto& src : {kData + "ct-ge-tilt", kBrain})
    for (const auto& f : fs::directory_iterator(src))
      if (f.is_regular_file() && f.path().filename() != "DIRFILE")
        fs::create_symlink(f.path(), study / (fs::path(src).filename().string() + "-" +
                                              f.path().filename().string()));
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  LoadOptions first;
  first.series = "";
  window_->open(study.string(), first);
  QVERIFY(shown.wait(120000));
  const std::string a = fixture_.models->document.volume()->study.seriesInstanceUid;
  focusView(window_->sliceView(0));
  QTest::keyClick(&window_->sliceView(0), Qt::Key_N);
  // Not a series further: the status bar says so at once, no load starts.
  const bool wentOn = shown.wait(30000);
  if (!wentOn) {  // the first was the last by series number: previous goes to the other
    focusView(window_->sliceView(0));
    QTest::keyClick(&window_->sliceView(0), Qt::Key_N, Qt::ShiftModifier);
    QVERIFY(shown.wait(120000));
  }
  const std::string b = fixture_.models->document.volume()->study.seriesInstanceUid;
  QVERIFY(!b.empty());
  QVERIFY(a != b);
  focusView(window_->sliceView(0));
  QTest::keyClick(&window_->sliceView(0), Qt::Key_N, wentOn ? Qt::ShiftModifier : Qt::NoModifier);
  QVERIFY(shown.wait(120000));
  QCOMPARE(fixture_.models->document.volume()->study.seriesInstanceUid, a);
}

// README's docs/images/reading-1plus3.png (run with VOXRAY_READING_SHOT=PATH under
// xvfb-run -s "-screen 0 1920x1080x24"): the Philips head CT in the 1+3 layout, a distance
// on slice 14 marked as a key image. Skipped otherwise.
// The layout goes into the session and comes back after another study hung differently;
// the layout last chosen is the next start's (no rule matches the phantom).
void ReadingTest::sessionKeepsTheLayoutAndTheNextStartRemembersIt() {
  struct Forget {
    ~Forget() { QSettings().remove("reading/lastLayout"); }
  } forget;
  window_->resize(1800, 1000);
  SliceView& axial = window_->sliceView(0);
  QWidget& volume = window_->volumeView();
  QTest::keyClick(&axial, Qt::Key_3, Qt::ControlModifier);  // 2x2: slices first, 3D last
  QCOMPARE(reading_->layout(), ViewLayout::TwoByTwo);
  QCOMPARE(QSettings().value("reading/lastLayout").toString(), QString("2x2"));
  auto isTwoByTwo = [&] {
    return axial.isVisible() && volume.isVisible() && axial.x() < window_->sliceView(1).x() &&
           axial.y() < window_->sliceView(2).y() && volume.x() > axial.x() &&
           volume.y() > axial.y();
  };
  QTRY_VERIFY(isTwoByTwo());
  const fs::path dir = freshDir("layout-session");
  SessionActions& sessions = window_->sessions();
  sessions.tell = [this](const QString& t, const QString& m) { errors_ << t + ": " + m; };
  const std::string file = (dir / "s.json").string();
  QVERIFY(sessions.saveTo(QString::fromStdString(file)));
  std::ifstream in(file);
  const auto saved = nlohmann::json::parse(in);
  QCOMPARE(saved["reading"]["layout"].get<std::string>(), std::string("2x2"));
  // Another study: the head CT hangs by the default rule "CT head" in MPR+3D.
  QSignalSpy shown(window_, &MainWindow::volumeShown);
  window_->open(kBrain, {});
  QVERIFY(shown.wait(120000));
  QCOMPARE(reading_->layout(), ViewLayout::MprPlus3d);
  QTRY_VERIFY(volume.x() < axial.x());  // 3D top left
  // The session: the phantom in 2x2 again, not hung by the rules.
  sessions.openFile(file);
  QVERIFY(shown.wait(120000));
  // The session's input: the embedded head phantom (no path), not the head CT.
  QVERIFY(fixture_.models->source.path.empty());
  QVERIFY(fixture_.models->document.volume()->study.seriesInstanceUid.empty());
  QCOMPARE(reading_->layout(), ViewLayout::TwoByTwo);
  QTRY_VERIFY(isTwoByTwo());
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  // The next start (a new window, no session): the layout last chosen, 2x2.
  PhantomWindow next;
  QVERIFY(next.start());
  auto* nextReading = next.window->findChild<ReadingActions*>();
  QVERIFY(nextReading);
  QCOMPARE(nextReading->layout(), ViewLayout::TwoByTwo);
  QVERIFY(next.window->volumeView().isVisible() && next.window->sliceView(2).isVisible());
  next.stop();
}

void ReadingTest::readmeScreenshot() {
  const QString shot = qEnvironmentVariable("VOXRAY_READING_SHOT");
  if (shot.isEmpty()) QSKIP("set VOXRAY_READING_SHOT=PATH to write the README's screenshot");
  Quality q = fixture_.models->render.quality();
  q.resolution = {0, 0};  // the view's size
  fixture_.models->render.setQuality(q);
  window_->resize(1900, 1040);
  openBrain();
  reading_->setLayout(ViewLayout::OnePlusThree);
  fixture_.models->crosshair.setVoxel({256, 256, 14});
  fixture_.models->measurements.add(MeasureKind::Distance, {{180, 200, 14}, {330, 310, 14}}, 2);
  // Without a window manager the window gets no focus for K: the action's own call.
  QVERIFY(results_->markKeyImage());
  // A camera change after the load: the frame waited for is the new volume's.
  fixture_.models->render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 20.0; });
  waitFullFrame(*window_);
  QTest::qWait(500);
  QVERIFY(window_->grab().save(shot));
}

}  // namespace voxray::ui::test
