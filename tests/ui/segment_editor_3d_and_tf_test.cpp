// A segment in the 3D view: its mask and surface in the frame, its own transfer function
// (a preset, the editor's drag, a new segment on a freed label) and From TF.
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

// dvr with a ball painted over the top of the skull: Show only leaves what the ball covers
// (fewer lit pixels, but some), Hide the rest, Off all of it again.
void SegmentEditorTest::shownMaskChangesThe3DFrame() {
  // The first sharp dvr frame rendered after CHANGE with the render state's mask then (a
  // frame asked for before the change may still arrive after it).
  auto frameAfter = [this](const std::function<void()>& change) {
    QSignalSpy spy(&fixture_.window->scheduler(), &RenderScheduler::frameReady);
    change();
    const RenderParams wanted = models().render.params();
    for (int tries = 0; tries < 600; ++tries) {
      while (!spy.isEmpty()) {
        auto f = spy.takeFirst().at(0).value<std::shared_ptr<const Frame>>();
        if (!f->interactive && f->params.mode == Mode::Dvr &&
            f->params.segmentMask == wanted.segmentMask)
          return toQImage(f->image);
      }
      spy.wait(100);
    }
    qFatal("no sharp dvr frame within 60 s");
  };
  const QImage all = frameAfter(
      [this] { models().render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; }); });
  const int allLit = litPixels(all);
  const uint8_t label = addSegment();
  // The skull's top: z semi-axis 0.79 of the 128 mm half box above a 5 mm offset.
  models().segmentation.paintSphere({32, 32, 56}, 28.0, label);
  QComboBox* mask = panel().findChild<QComboBox*>("segmentMask3d");
  const QImage shownFrame =
      frameAfter([mask] { mask->setCurrentIndex(int(MaskChoice::ShowOnly)); });
  QCOMPARE(toString(models().render.params().segmentMask), std::string("show:1"));
  const int shown = litPixels(shownFrame);
  const int off = litPixels(frameAfter([mask] { mask->setCurrentIndex(int(MaskChoice::Off)); }));
  // A ball over the whole head, hidden: nothing is left (the edit reaches the 3D view too).
  models().segmentation.paintSphere({32, 32, 32}, 400.0, label);
  const int hidden =
      litPixels(frameAfter([mask] { mask->setCurrentIndex(int(MaskChoice::Hide)); }));
  qInfo("lit pixels: all %d, show only %d, off again %d, hide all %d", allLit, shown, off, hidden);
  QVERIFY(shown > 50);
  QVERIFY(shown < allLit * 3 / 4);
  QVERIFY(std::abs(off - allLit) <= allLit / 50);  // back to the whole head (the blend tints it)
  QCOMPARE(hidden, 0);
}

// The list's "3D" choice (issue 34): a sphere painted in the air before the face shows
// nothing in the volume (air is transparent in the dvr); switched to Surface, the 3D frame
// changes, and only at the sphere's pixels (rays passing within its radius, plus the
// voxelisation's and smoothing's reach); Hidden gives the first frame back.
void SegmentEditorTest::surfaceChoiceChangesThe3DFrameAtTheSegment() {
  models().render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; });
  const uint8_t label = addSegment();
  const glm::dvec3 centre(14, 6, 14);  // voxels of 4 mm: right, anterior, low; in the air
  const double radiusMm = 20.0;
  models().segmentation.paintSphere(centre, radiusMm, label);
  const QImage inVolume = test::settledFrame(*fixture_.window);
  auto* box = panel().findChild<QComboBox*>("segmentDisplay3d");
  QVERIFY(box);
  QCOMPARE(box->currentText(), QString("In volume"));
  box->setCurrentIndex(box->findText("Surface"));
  QCOMPARE(models().segmentation.segmentation().find(label)->display3d,
           Segment::Display3d::Surface);
  const QImage surface = test::changedFrame(*fixture_.window, inVolume);
  QCOMPARE(surface.size(), inVolume.size());
  // Each pixel's ray's distance from the sphere's centre (world: mm from the volume centre).
  RenderParams p = models().render.params();
  p.width = surface.width();
  p.height = surface.height();
  const ViewGeometry g = makeViewGeometry(*models().document.volume(), p);
  const glm::dvec3 c = glm::inverse(g.worldToVoxel) * (centre - g.voxelCentre);
  int changed = 0, changedOff = 0, inner = 0, innerChanged = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      glm::dvec3 o, d;
      g.ray(x, y, p.width, p.height, o, d);
      const double dist = glm::length(glm::cross(c - o, d));
      const bool differs = surface.pixel(x, y) != inVolume.pixel(x, y);
      changed += differs;
      // A voxel's half diagonal (3.5 mm) and a pixel (2.7 mm here) beyond the radius.
      changedOff += differs && dist > radiusMm + 7.0;
      if (dist < radiusMm - 7.0) inner += 1, innerChanged += differs;
    }
  qInfo("surface: %d pixels changed, %d beyond the sphere; %d of %d inner pixels", changed,
        changedOff, innerChanged, inner);
  QVERIFY(inner > 20);
  QCOMPARE(innerChanged, inner);
  QCOMPARE(changedOff, 0);
  box->setCurrentIndex(box->findText("Hidden"));
  const QImage hidden = test::changedFrame(*fixture_.window, surface);
  QCOMPARE(test::differingPixels(hidden, inVolume), 0);
}

// Issue 35: the Segments panel's TF… combo gives the chosen segment CT-Bone as its own
// transfer function: the 3D frame changes only where the segment (a ball over the skull's
// top) shows, and Edit → Undo (Ctrl+Z, the 3D view focused) brings back exactly the frame
// before. Where the segment shows: the lit pixels of Show-only frames under either table
// (a ray's pixel can change only where a sample of the segment shows under one of them),
// grown by a pixel for rays that graze its edge; a change counts above 2 levels (a sample
// too faint to light a Show-only pixel may still move a rounding by one level).
void SegmentEditorTest::segmentTfPresetChangesItsPixelsAndUndoRestores() {
  models().render.update(kAppearance | kCamera, [](RenderParams& p) {
    p.mode = Mode::Dvr;
    p.preset = "CT-Skin";
    p.camera.azimuthDeg = 30.0;
    p.camera.elevationDeg = 70.0;  // from above: the ball's scalp and skull face the camera
  });
  const uint8_t label = addSegment();
  models().segmentation.paintSphere({32, 32, 56}, 28.0, label);
  const QImage before = test::settledFrame(*fixture_.window);
  QComboBox* tf = panel().findChild<QComboBox*>("segmentTf");
  QComboBox* mask = panel().findChild<QComboBox*>("segmentMask3d");
  QVERIFY(tf && mask);
  QCOMPARE(tf->currentText(), QString("Volume's"));
  mask->setCurrentIndex(int(MaskChoice::ShowOnly));
  const QImage showSkin = test::changedFrame(*fixture_.window, before);
  tf->setCurrentIndex(tf->findText("CT-Bone"));
  QCOMPARE(models().render.params().segmentTfs.count(label), size_t(1));
  QVERIFY(models().render.params().segmentTfs.at(label) == findPreset("CT-Bone").tf.points);
  const QImage showBone = test::changedFrame(*fixture_.window, showSkin);
  mask->setCurrentIndex(int(MaskChoice::Off));
  const QImage bone = test::changedFrame(*fixture_.window, showBone);
  QCOMPARE(bone.size(), before.size());
  const SegmentChange c = changeWhereTheSegmentShows(before, bone, showSkin, showBone);
  qInfo("segment TF: %d pixels changed, %d outside the %d where the segment shows", c.changed,
        c.outside, c.shown);
  QVERIFY(c.changed > 50);
  QCOMPARE(c.outside, 0);
  QVERIFY(c.shown < before.width() * before.height() / 2);  // the ball, not the whole frame
  fixture_.window->volumeView().setFocus();                 // not the Segments panel (its own undo)
  QTest::keyClick(fixture_.window.get(), Qt::Key_Z, Qt::ControlModifier);
  QVERIFY(models().render.params().segmentTfs.empty());
  QCOMPARE(tf->currentText(), QString("Volume's"));
  const QImage restored = test::changedFrame(*fixture_.window, bone);
  QCOMPARE(test::differingPixels(restored, before), 0);
}

// Issue 35: TF… Edit opens the transfer-function editor on the chosen segment's own table
// (CT-Bone, over the volume's CT-Skin). Dragging its bone point (641 HU, 0.72) to (400 HU, 0.15):
// bone turns faint. That changes that segment's table only (the volume keeps CT-Skin), the 3D
// frame only where the segment shows (as in segmentTfPresetChangesItsPixelsAndUndoRestores: the
// lit pixels of Show-only frames under either table, grown by a pixel; a change counts above 2
// levels), and the editor's undo gives the frame before back exactly.
void SegmentEditorTest::segmentTfEditorDragChangesOnlyThatSegmentsPixels() {
  MainWindow& window = *fixture_.window;
  models().render.update(kAppearance | kCamera, [](RenderParams& p) {
    p.mode = Mode::Dvr;
    p.preset = "CT-Skin";
    p.camera.azimuthDeg = 30.0;
    p.camera.elevationDeg = 70.0;  // from above: the ball's scalp and skull face the camera
  });
  const uint8_t label = addSegment();
  models().segmentation.paintSphere({32, 32, 56}, 28.0, label);
  QComboBox* tf = panel().findChild<QComboBox*>("segmentTf");
  QComboBox* mask = panel().findChild<QComboBox*>("segmentMask3d");
  auto* edit = panel().findChild<QPushButton*>("segmentTfEdit");
  QVERIFY(tf && mask && edit);
  tf->setCurrentIndex(tf->findText("CT-Bone"));
  const QImage before = test::settledFrame(window);
  mask->setCurrentIndex(int(MaskChoice::ShowOnly));
  const QImage showBefore = test::changedFrame(window, before);
  mask->setCurrentIndex(int(MaskChoice::Off));
  QCOMPARE(test::differingPixels(test::changedFrame(window, showBefore), before), 0);

  edit->click();
  auto* editor = window.findChild<TfEditorDialog*>("tfEditor");
  QVERIFY(editor && editor->isVisible());
  QCOMPARE(int(editor->model().target()), int(label));
  QVERIFY(editor->windowTitle().contains(QString("segment %1").arg(label)));
  QCOMPARE(renderTable(editor->model().property()), findPreset("CT-Bone").tf.points);
  TfCurveView& curve = editor->curve();
  curve.setHuRange(-1000.0, 2000.0);
  QVERIFY(QTest::qWaitForWindowExposed(editor));
  const QPoint at(int(std::lround(curve.xOf(641.0))), int(std::lround(curve.yOf(0.72))));
  const QPoint to(int(std::lround(curve.xOf(400.0))), int(std::lround(curve.yOf(0.15))));
  QTest::mousePress(&curve, Qt::LeftButton, {}, at);
  QTest::mouseMove(&curve, (at + to) / 2);
  QTest::mouseMove(&curve, to);
  QTest::mouseRelease(&curve, Qt::LeftButton, {}, to);
  const RenderParams& p = models().render.params();
  QCOMPARE(p.segmentTfs.count(label), size_t(1));
  QCOMPARE(p.segmentTfs.at(label), renderTable(editor->model().property()));
  // The point is at 400 HU and 0.15 within a pixel of the axes (3000 HU over the curve's
  // width, opacity 1 over its height).
  auto sel = curve.selection();
  QVERIFY(sel && sel->list == TfCurveView::List::Opacity);
  const OpacityNode moved = editor->model().property().opacity[sel->index];
  QVERIFY2(std::abs(moved.x - 400.0) <= 3000.0 / curve.curveArea().width(),
           qPrintable(QString::number(moved.x)));
  QVERIFY(std::abs(moved.opacity - 0.15) <= 1.0 / curve.curveArea().height());
  QCOMPARE(p.preset, std::string("CT-Skin"));  // the volume's table as it was
  QVERIFY(p.transferFunction.empty());
  QVERIFY(editor->model().canUndo());

  const QImage after = test::changedFrame(window, before);
  mask->setCurrentIndex(int(MaskChoice::ShowOnly));
  const QImage showAfter = test::changedFrame(window, after);
  mask->setCurrentIndex(int(MaskChoice::Off));
  QCOMPARE(test::differingPixels(test::changedFrame(window, showAfter), after), 0);
  const SegmentChange c = changeWhereTheSegmentShows(before, after, showBefore, showAfter);
  qInfo("segment TF edit: %d pixels changed, %d outside the %d where the segment shows", c.changed,
        c.outside, c.shown);
  QVERIFY(c.changed > 50);
  QCOMPARE(c.outside, 0);
  QVERIFY(c.shown < before.width() * before.height() / 2);  // the ball, not the whole frame

  editor->model().undo();  // the drag was one step
  QCOMPARE(models().render.params().segmentTfs.at(label), findPreset("CT-Bone").tf.points);
  QCOMPARE(test::differingPixels(test::changedFrame(window, after), before), 0);
}

// A removed segment's table stays with its label (undo brings both back); a new segment
// that gets the label again starts with the volume's table, not the removed one's.
void SegmentEditorTest::aNewSegmentOnAFreedLabelStartsWithTheVolumesTf() {
  const uint8_t label = addSegment();
  QComboBox* tf = panel().findChild<QComboBox*>("segmentTf");
  QVERIFY(tf);
  tf->setCurrentIndex(tf->findText("CT-Bone"));
  QCOMPARE(models().render.params().segmentTfs.count(label), size_t(1));
  panel().findChild<QPushButton*>("segmentRemove")->click();
  QCOMPARE(models().render.params().segmentTfs.count(label), size_t(1));
  QCOMPARE(addSegment(), label);  // the lowest free label
  QCOMPARE(models().render.params().segmentTfs.count(label), size_t(0));
  QCOMPARE(tf->currentText(), QString("Volume's"));
}

// From TF: the range becomes the 3D view's opaque HU range (dvr table), or iso's range
// (both inside the 64³ phantom's values, -1000 ... 965 HU, so not clamped).
void SegmentEditorTest::fromTfTakesTheTransferFunctionsOpaqueRange() {
  models().render.update(kAppearance, [](RenderParams& p) {
    p.mode = Mode::Dvr;
    const glm::dvec3 c(1.0);
    p.transferFunction = {{-500, glm::dvec4(c, 0)},
                          {250, glm::dvec4(c, 0)},
                          {600, glm::dvec4(c, 0.5)},
                          {900, glm::dvec4(c, 0)}};
  });
  auto* fromTf = panel().findChild<QPushButton*>("segmentFromTf");
  fromTf->click();
  QCOMPARE(models().segmentTools.settings().range.lo, 250.0);
  QCOMPARE(models().segmentTools.settings().range.hi, 900.0);
  QCOMPARE(panel().findChild<QDoubleSpinBox*>("segmentLo")->value(), 250.0);
  QCOMPARE(panel().findChild<QDoubleSpinBox*>("segmentHi")->value(), 900.0);
  models().render.update(kAppearance, [](RenderParams& p) {
    p.mode = Mode::Iso;
    p.isoLo = 700;
    p.isoHi = 900;
  });
  fromTf->click();
  QCOMPARE(models().segmentTools.settings().range.lo, 700.0);
  QCOMPARE(models().segmentTools.settings().range.hi, 900.0);
  QVERIFY(errors_.isEmpty());
}

}  // namespace voxray::ui
