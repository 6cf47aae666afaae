// The segment editor's tools in the views: the Segments dock, painting and its undo, the
// threshold preview, the CLI twin's label map, the 3D view's scissors and Ctrl+click, and
// Edit → Undo/Redo in the order made.
#include <cmath>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMainWindow>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>

#include "qt_image.h"
#include "segment_editor_test.h"
#include "segment_overlay.h"
#include "segment_panel.h"
#include "slice_view.h"
#include "study_state.h"
#include "tf_editor_dialog.h"
#include "voxray/engine/camera.h"
#include "voxray/io/orientation.h"
#include "voxray/io/phantom.h"
#include "voxray/io/raw_import.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif

namespace voxray::ui {

// View → Segments (Ctrl+Shift+S) shows and hides the dock.
void SegmentEditorTest::viewMenuTogglesTheSegmentsDock() {
  QDockWidget* dock = fixture_.window->segmentDock();
  QAction* show = fixture_.window->findChild<QAction*>("viewSegments");
  QVERIFY(fixture_.window->menuBar()->actions().size() > 0);
  QVERIFY(show);
  QCOMPARE(show->shortcut(), QKeySequence("Ctrl+Shift+S"));
  dock->close();
  QVERIFY(!dock->isVisible());
  show->trigger();
  QVERIFY(dock->isVisible());
}

// A 10 mm disc painted at a click: exactly the voxels of the axial slice whose centres lie
// within 10 mm of the clicked point (counted here independently), the overlay shows the
// segment's colour there, and Undo gives back the empty label map.
void SegmentEditorTest::paintedDiscChangesItsVoxelsAndUndoRestores() {
  const Volume& v = *models().document.volume();
  const uint8_t label = addSegment();
  QCOMPARE(label, uint8_t(1));
  models().segmentation.setColour(label, {1.0f, 0.0f, 0.0f});
  setTool([](SegmentToolSettings& s) {
    s.tool = SegmentTool::Paint;
    s.radiusMm = 10.0;
    s.sphere = false;
  });
  const int slice = models().crosshair.sliceOf(axial().axes());
  glm::dvec3 target(30, 34, 0);
  target[axial().axes().nAxis] = slice;
  const QPoint click = widgetOf(target);
  const glm::dvec3 c = voxelAt(click);
  QVERIFY(glm::length(c - target) < 0.5);  // within half a voxel of the voxel's centre
  QTest::mouseClick(&axial(), Qt::LeftButton, {}, click);
  // The disc's voxels: centres within 10 mm of c in slice `slice` (4 mm voxels: ~20).
  size_t expected = 0;
  for (int j = 0; j < v.dims.y; ++j)
    for (int i = 0; i < v.dims.x; ++i) {
      const double dx = (i - c.x) * v.spacingMm.x, dy = (j - c.y) * v.spacingMm.y;
      expected += dx * dx + dy * dy <= 100.0;
    }
  const Segmentation& seg = models().segmentation.segmentation();
  QCOMPARE(countLabel(seg, label), expected);
  QVERIFY(expected >= 16 && expected <= 26);  // pi * 2.5^2 = 19.6 voxels, ± the ring
  QCOMPARE(seg.labels[v.index(30, 34, slice)], label);
  // The overlay over the clicked voxel: the segment's red, at half its opacity.
  const QImage& o = axial().segmentOverlayImage();
  QVERIFY(!o.isNull());
  const glm::dvec2 s = voxelToSlice(axial().axes(), v.dims, target);
  const QColor at = o.pixelColor(int(s.x * o.width() / v.dims[axial().axes().uAxis]),
                                 int(s.y * o.height() / v.dims[axial().axes().vAxis]));
  QCOMPARE(at.red(), 255);
  QCOMPARE(at.green(), 0);
  QCOMPARE(at.blue(), 0);
  QCOMPARE(at.alpha(), int(std::lround(255 * kSegmentFillShare)));
  // A drag is one undo step too; the panel's Undo takes back the drag, then the click.
  const auto afterClick = seg.labels;
  QTest::mousePress(&axial(), Qt::LeftButton, {}, widgetOf(target + glm::dvec3(0, 8, 0)));
  for (int k = 1; k <= 6; ++k)
    QTest::mouseMove(&axial(), widgetOf(target + glm::dvec3(k * 2, 8, 0)));
  QTest::mouseRelease(&axial(), Qt::LeftButton, {}, widgetOf(target + glm::dvec3(12, 8, 0)));
  QVERIFY(countLabel(seg, label) > expected + 40);
  panel().findChild<QPushButton*>("segmentUndo")->click();
  QVERIFY(seg.labels == afterClick);
  panel().findChild<QPushButton*>("segmentUndo")->click();
  QCOMPARE(countLabel(seg, label), size_t(0));
  QVERIFY(errors_.isEmpty());
}

// The preview's voxels in the axial slice are the threshold's: after Apply the segment
// holds exactly that many there.
void SegmentEditorTest::thresholdPreviewCountEqualsTheMask() {
  const Volume& v = *models().document.volume();
  const uint8_t label = addSegment();
  setTool([](SegmentToolSettings& s) {
    s.tool = SegmentTool::Threshold;
    s.range = {700, 3000};
  });
  const size_t preview = axial().thresholdPreviewVoxels();
  QVERIFY(preview > 20);  // the skull's ring
  QVERIFY(!axial().thresholdPreviewImage().isNull());
  panel().findChild<QPushButton*>("segmentApplyThreshold")->click();
  const int slice = models().crosshair.sliceOf(axial().axes());
  size_t inSlice = 0;
  for (int y = 0; y < v.dims.y; ++y)
    for (int x = 0; x < v.dims.x; ++x)
      inSlice += models().segmentation.segmentation().labels[v.index(x, y, slice)] == label;
  QCOMPARE(inSlice, preview);
  // The statistics table: the segment's voxels as counted here, copied tab-separated.
  const size_t voxels = countLabel(models().segmentation.segmentation(), label);
  panel().updateStatistics();
  const QStringList lines = panel().statisticsText().split('\n', Qt::SkipEmptyParts);
  QCOMPARE(lines.size(), 2);
  QVERIFY(lines[0].startsWith("Segment\tVoxels\tVolume mL"));
  const QStringList cells = lines[1].split('\t');
  QCOMPARE(cells[0], QString("Segment 1"));
  QCOMPARE(cells[1], QString::number(voxels));
  // 4 mm voxels: 0.064 mL each.
  QCOMPARE(cells[2], QString::number(voxels * 0.064, 'f', 3));
  // A name typed into the list is one undo step of the model.
  auto* list = panel().findChild<QTableWidget*>("segmentList");
  list->item(0, 2)->setText("Bone");
  QCOMPARE(models().segmentation.segmentation().segments[0].name, std::string("Bone"));
  panel().findChild<QPushButton*>("segmentUndo")->click();
  QCOMPARE(models().segmentation.segmentation().segments[0].name, std::string("Segment 1"));
  QCOMPARE(list->item(0, 2)->text(), QString("Segment 1"));
  // From W/L: level ± width / 2.
  models().windowLevel.set({400, 40});
  panel().findChild<QPushButton*>("segmentFromWindow")->click();
  QCOMPARE(models().segmentTools.settings().range.lo, -160.0);
  QCOMPARE(models().segmentTools.settings().range.hi, 240.0);
}

// The seeded-region click and voxray-cli segment --threshold --seed --connectivity give the
// same label map byte for byte (.labels.raw).
void SegmentEditorTest::cliTwinWritesTheSameLabelMap() {
  const Volume& v = *models().document.volume();
  addSegment();
  setTool([](SegmentToolSettings& s) {
    s.tool = SegmentTool::Seed;
    s.range = {700, 3000};
    s.connectivity = Connectivity::Full26;
  });
  // A skull voxel of the axial slice: outward along the screen's x from the centre.
  const int slice = models().crosshair.sliceOf(axial().axes());
  glm::ivec3 seed(-1);
  for (int x = v.dims.x - 1; x > v.dims.x / 2 && seed.x < 0; --x) {
    glm::ivec3 p(v.dims.x / 2);
    p[axial().axes().uAxis] = x;
    p[axial().axes().nAxis] = slice;
    if (v.toPhysical(v.at(p.x, p.y, p.z)) >= 700) seed = p;
  }
  QVERIFY(seed.x >= 0);
  const QPoint click = widgetOf(glm::dvec3(seed));
  QCOMPARE(nearestVoxel(voxelAt(click)), seed);
  QTest::mouseClick(&axial(), Qt::LeftButton, {}, click);
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  QVERIFY(countLabel(models().segmentation.segmentation(), 1) > 1000);
  QTemporaryDir dir;
  const QString mine = dir.filePath("workstation.labels.raw");
  const QString cli = dir.filePath("cli.labels.raw");
  QVERIFY(panel().exportTo(mine));
  QProcess p;
  p.start(VOXRAY_CLI, {"segment", "--phantom-size", "64", "--threshold", "700,3000", "--seed",
                       QString("%1:%2:%3").arg(seed.x).arg(seed.y).arg(seed.z), "--connectivity",
                       "26", "-o", cli});
  QVERIFY(p.waitForFinished(60000));
  QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
  const std::string a = readAll(mine), b = readAll(cli);
  QCOMPARE(a.size(), v.voxelCount());
  QVERIFY(a == b);
}

// Scissors: a lasso around the whole 3D image removes the segment (what lies behind it),
// one undo step; with no segment chosen the status bar says so.
void SegmentEditorTest::scissorsLassoInThe3DViewCutsOneUndoStep() {
  const uint8_t label = addSegment();
  models().segmentation.paintSphere({32, 32, 32}, 20.0, label);
  const size_t ball = countLabel(models().segmentation.segmentation(), label);
  QVERIFY(ball > 100);
  setTool([](SegmentToolSettings& s) { s.tool = SegmentTool::Scissors; });
  VolumeView& view = fixture_.window->volumeView();
  const QRect r = view.imageRect();
  const QPoint corners[] = {r.topLeft() + QPoint(2, 2), r.topRight() + QPoint(-2, 2),
                            r.bottomRight() + QPoint(-2, -2), r.bottomLeft() + QPoint(2, -2)};
  QTest::mousePress(&view, Qt::LeftButton, {}, corners[0]);
  for (const QPoint& c : corners) QTest::mouseMove(&view, c);
  QTest::mouseRelease(&view, Qt::LeftButton, {}, corners[3]);
  QCOMPARE(countLabel(models().segmentation.segmentation(), label), size_t(0));
  QCOMPARE(QString::fromStdString(models().segmentation.undoText()), QString("Undo Scissors"));
  models().segmentation.undo();
  QCOMPARE(countLabel(models().segmentation.segmentation(), label), ball);
  // Ticked "keep only inside": the same lasso around the whole image keeps the whole ball;
  // one in the image's top-left corner, clear of the ball, keeps nothing.
  panel().findChild<QCheckBox*>("segmentScissorsKeep")->setChecked(true);
  QVERIFY(models().segmentTools.settings().scissorsKeep);
  QTest::mousePress(&view, Qt::LeftButton, {}, corners[0]);
  for (const QPoint& c : corners) QTest::mouseMove(&view, c);
  QTest::mouseRelease(&view, Qt::LeftButton, {}, corners[3]);
  QCOMPARE(countLabel(models().segmentation.segmentation(), label), ball);
  const QPoint corner[] = {r.topLeft() + QPoint(2, 2), r.topLeft() + QPoint(12, 2),
                           r.topLeft() + QPoint(12, 12), r.topLeft() + QPoint(2, 12)};
  QTest::mousePress(&view, Qt::LeftButton, {}, corner[0]);
  for (const QPoint& c : corner) QTest::mouseMove(&view, c);
  QTest::mouseRelease(&view, Qt::LeftButton, {}, corner[3]);
  QCOMPARE(countLabel(models().segmentation.segmentation(), label), size_t(0));
  QCOMPARE(QString::fromStdString(models().segmentation.undoText()), QString("Undo Scissors keep"));
}

// With a segment tool chosen, Ctrl+click in the 3D view picks the segment it hits (the
// skull, seen from the front) and the list selects it.
void SegmentEditorTest::ctrlClickIn3DPicksTheSegment() {
  const uint8_t other = addSegment();
  models().segmentation.paintSphere({32, 32, 32}, 8.0, other);  // inside the head: unseen
  const uint8_t skull = addSegment();
  setTool([](SegmentToolSettings& s) {
    s.tool = SegmentTool::Threshold;
    s.range = {700, 3000};
  });
  panel().findChild<QPushButton*>("segmentApplyThreshold")->click();
  panel().selectLabel(other);
  QCOMPARE(models().segmentTools.settings().label, other);
  VolumeView& view = fixture_.window->volumeView();
  QSignalSpy picked(&fixture_.window->scheduler(), &RenderScheduler::pickReady);
  QTest::mouseClick(&view, Qt::LeftButton, Qt::ControlModifier, view.imageRect().center());
  QVERIFY(picked.wait(60000));
  QCoreApplication::processEvents();
  QCOMPARE(models().segmentTools.settings().label, skull);
  QCOMPARE(panel().currentLabel(), skull);
  QVERIFY(models().measurements.items().empty());  // no measurement point was added
}

// Edit → Undo (Ctrl+Z) and Redo (Ctrl+Shift+Z) take back segment edits and view changes in
// the order made: a painted disc's voxels go and come back, then the camera turn before it.
void SegmentEditorTest::editMenuUndoAndRedoTakeBackAPaintInTheOrderMade() {
  const uint8_t label = addSegment();
  models().render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 40.0; });
  setTool([](SegmentToolSettings& s) {
    s.tool = SegmentTool::Paint;
    s.radiusMm = 10.0;
    s.sphere = false;
  });
  const int slice = models().crosshair.sliceOf(axial().axes());
  glm::dvec3 target(30, 34, 0);
  target[axial().axes().nAxis] = slice;
  QTest::mouseClick(&axial(), Qt::LeftButton, {}, widgetOf(target));
  const Segmentation& seg = models().segmentation.segmentation();
  const auto painted = seg.labels;
  const size_t n = countLabel(seg, label);
  QVERIFY2(n >= 16 && n <= 26, qPrintable(QString::number(n)));  // a 10 mm disc, 4 mm voxels
  QMainWindow* w = fixture_.window.get();
  QAction* undo = w->findChild<QAction*>("editUndo");
  QVERIFY(undo && undo->isEnabled());
  QCOMPARE(undo->toolTip(), QString::fromStdString(models().segmentation.undoText()));
  w->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(w));
  axial().setFocus();  // the slice view, not the Segments panel: the last edit goes first
  QTest::keyClick(w, Qt::Key_Z, Qt::ControlModifier);
  QCOMPARE(countLabel(seg, label), size_t(0));
  QCOMPARE(models().render.params().camera.azimuthDeg, 40.0);
  QTest::keyClick(w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  QCOMPARE(countLabel(seg, label), n);
  QVERIFY(seg.labels == painted);
  QTest::keyClick(w, Qt::Key_Z, Qt::ControlModifier);
  QTest::keyClick(w, Qt::Key_Z, Qt::ControlModifier);  // the turn, made before the paint
  QCOMPARE(countLabel(seg, label), size_t(0));
  QCOMPARE(models().render.params().camera.azimuthDeg, 0.0);
  QCOMPARE(seg.segments.size(), size_t(1));  // added before the turn: still there
  QVERIFY(errors_.isEmpty());
}

}  // namespace voxray::ui
