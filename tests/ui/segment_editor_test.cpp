// The workstation's segment editor (issue 34) driven through the real widgets: the Segments
// dock, the slice views' tools and overlays, undo, the 3D view's mask, export and import, and
// the CLI twin (voxray-cli segment writes the label map the seeded-region click makes).
#include <cmath>
#include <fstream>
#include <iterator>

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
#include "segment_overlay.h"
#include "segment_panel.h"
#include "slice_view.h"
#include "study_state.h"
#include "tf_editor_dialog.h"
#include "voxray/engine/camera.h"
#include "voxray/io/orientation.h"
#include "voxray/io/phantom.h"
#include "voxray/io/raw_import.h"
#include "window_fixture.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif

namespace voxray::ui {

namespace {

size_t countLabel(const Segmentation& s, uint8_t label) {
  size_t n = 0;
  for (uint8_t l : s.labels) n += l == label;
  return n;
}

std::string readAll(const QString& path) {
  std::ifstream in(path.toStdString(), std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Pixels of a frame that are not its background (black).
int litPixels(const QImage& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += (image.pixel(x, y) & 0xffffff) != 0;
  return n;
}

}  // namespace

class SegmentEditorTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;
  QStringList errors_;

  AppModels& models() { return *fixture_.models; }
  SegmentPanel& panel() { return fixture_.window->segments(); }
  SliceView& axial() { return fixture_.window->sliceView(0); }

  void setTool(const std::function<void(SegmentToolSettings&)>& edit) {
    SegmentToolSettings s = models().segmentTools.settings();
    edit(s);
    models().segmentTools.set(s);
  }
  // Where in the axial view a voxel's centre is drawn (the nearest whole widget pixel).
  QPoint widgetOf(glm::dvec3 voxel) {
    const glm::dvec2 s = voxelToSlice(axial().axes(), models().document.volume()->dims, voxel);
    return axial().toWidget(s.x, s.y).toPoint();
  }
  // The voxel position the view takes for a click at P (its own mapping, public parts).
  glm::dvec3 voxelAt(QPoint p) {
    const glm::dvec2 s = axial().toSlice(QPointF(p));
    return models().crosshair.viewToVoxel(axial().axes(), s.x, s.y);
  }
  uint8_t addSegment() {
    fixture_.window->segmentDock()->show();
    auto* add = panel().findChild<QPushButton*>("segmentAdd");
    add->click();
    return panel().currentLabel();
  }

  // The pixels of AFTER more than 2 levels from BEFORE in a channel, and of those the ones
  // outside where the segment shows (lit in SHOW_A or SHOW_B, grown by one pixel).
  struct SegmentChange {
    int changed = 0, outside = 0, shown = 0;
  };
  static SegmentChange changeWhereTheSegmentShows(const QImage& before, const QImage& after,
                                                  const QImage& showA, const QImage& showB) {
    auto lit = [](const QImage& a, int x, int y) {
      return x >= 0 && y >= 0 && x < a.width() && y < a.height() && (a.pixel(x, y) & 0xffffff);
    };
    SegmentChange c;
    for (int y = 0; y < before.height(); ++y)
      for (int x = 0; x < before.width(); ++x) {
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            near = near || lit(showA, x + dx, y + dy) || lit(showB, x + dx, y + dy);
        c.shown += near;
        const QRgb a = before.pixel(x, y), b = after.pixel(x, y);
        if (std::abs(qRed(a) - qRed(b)) > 2 || std::abs(qGreen(a) - qGreen(b)) > 2 ||
            std::abs(qBlue(a) - qBlue(b)) > 2) {
          ++c.changed;
          c.outside += !near;
        }
      }
    return c;
  }

  // The README figures' scene: CThead (in HU) in a 1900 x 1040 window, dvr CT-Bone turned by
  // 30 degrees, and a "Skull" segment (threshold 300 ... 3000 HU, largest island) in its colour.
  void openCtheadWithASkullSegment() {
    RawLayout l;  // voxray-cli's --raw-dims 256,256 --raw-type i16 --raw-endian big ...
    l.dims = {256, 256, 0};
    l.type = SampleType::I16;
    l.order = ByteOrder::Big;
    l.spacingMm = {1.0, 1.0, 2.0};
    l.slope = 1.0;
    l.intercept = -1024.0;
    l.direction = directionFromAxesCode("LPI");
    auto v = std::make_shared<const Volume>(
        importRaw(std::string(VOXRAY_DATA_DIR) + "/stanford/CThead", l));
    Quality q = models().render.quality();
    q.resolution = {0, 0};  // the view's size
    models().render.setQuality(q);
    fixture_.window->resize(1900, 1040);
    openStudy(models(), v, "CThead");
    models().render.update(kAppearance | kCamera, [](RenderParams& p) {
      p.mode = Mode::Dvr;
      p.preset = "CT-Bone";
      p.camera.azimuthDeg = 30.0;
    });
    const uint8_t label = addSegment();
    models().segmentation.rename(label, "Skull");
    setTool([](SegmentToolSettings& s) {
      s.tool = SegmentTool::Threshold;
      s.range = {300, 3000};
    });
    panel().findChild<QPushButton*>("segmentApplyThreshold")->click();
    panel()
        .findChild<QComboBox*>("segmentOperation")
        ->setCurrentIndex(int(MaskOperation::KeepLargest));
    panel().findChild<QPushButton*>("segmentApplyOperation")->click();
    setTool([](SegmentToolSettings& s) { s.tool = SegmentTool::None; });
    models().segmentation.setColour(label, {0.95f, 0.75f, 0.35f});
  }

 private slots:
  void init() {
    QVERIFY(fixture_.start());
    errors_.clear();
    fixture_.window->setErrorSink(
        [this](const QString& t, const QString& m) { errors_ << t + ": " + m; });
  }
  void cleanup() { fixture_.stop(); }

  // View → Segments (Ctrl+Shift+S) shows and hides the dock.
  void viewMenuTogglesTheSegmentsDock() {
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
  void paintedDiscChangesItsVoxelsAndUndoRestores() {
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
  void thresholdPreviewCountEqualsTheMask() {
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

  // dvr with a ball painted over the top of the skull: Show only leaves what the ball covers
  // (fewer lit pixels, but some), Hide the rest, Off all of it again.
  void shownMaskChangesThe3DFrame() {
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
    const QImage all = frameAfter([this] {
      models().render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; });
    });
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
    qInfo("lit pixels: all %d, show only %d, off again %d, hide all %d", allLit, shown, off,
          hidden);
    QVERIFY(shown > 50);
    QVERIFY(shown < allLit * 3 / 4);
    QVERIFY(std::abs(off - allLit) <= allLit / 50);  // back to the whole head (the blend tints it)
    QCOMPARE(hidden, 0);
  }

  // Issue 35: the Segments panel's TF… combo gives the chosen segment CT-Bone as its own
  // transfer function: the 3D frame changes only where the segment (a ball over the skull's
  // top) shows, and Edit → Undo (Ctrl+Z, the 3D view focused) brings back exactly the frame
  // before. Where the segment shows: the lit pixels of Show-only frames under either table
  // (a ray's pixel can change only where a sample of the segment shows under one of them),
  // grown by a pixel for rays that graze its edge; a change counts above 2 levels (a sample
  // too faint to light a Show-only pixel may still move a rounding by one level).
  void segmentTfPresetChangesItsPixelsAndUndoRestores() {
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
    fixture_.window->volumeView().setFocus();  // not the Segments panel (its own undo)
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
  void segmentTfEditorDragChangesOnlyThatSegmentsPixels() {
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
    qInfo("segment TF edit: %d pixels changed, %d outside the %d where the segment shows",
          c.changed, c.outside, c.shown);
    QVERIFY(c.changed > 50);
    QCOMPARE(c.outside, 0);
    QVERIFY(c.shown < before.width() * before.height() / 2);  // the ball, not the whole frame

    editor->model().undo();  // the drag was one step
    QCOMPARE(models().render.params().segmentTfs.at(label), findPreset("CT-Bone").tf.points);
    QCOMPARE(test::differingPixels(test::changedFrame(window, after), before), 0);
  }

  // The list's "3D" choice (issue 34): a sphere painted in the air before the face shows
  // nothing in the volume (air is transparent in the dvr); switched to Surface, the 3D frame
  // changes, and only at the sphere's pixels (rays passing within its radius, plus the
  // voxelisation's and smoothing's reach); Hidden gives the first frame back.
  void surfaceChoiceChangesThe3DFrameAtTheSegment() {
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

  // A removed segment's table stays with its label (undo brings both back); a new segment
  // that gets the label again starts with the volume's table, not the removed one's.
  void aNewSegmentOnAFreedLabelStartsWithTheVolumesTf() {
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

  // The seeded-region click and voxray-cli segment --threshold --seed --connectivity give the
  // same label map byte for byte (.labels.raw).
  void cliTwinWritesTheSameLabelMap() {
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

  // Export never replaces a file unless the user says yes; Import of a label map made on
  // another grid is refused with the difference shown and keeps the segments.
  void exportAsksBeforeReplacingAndImportShowsAMismatch() {
    addSegment();
    models().segmentation.paintSphere({32, 32, 32}, 12.0, 1);
    QTemporaryDir dir;
    const QString path = dir.filePath("seg.labels.raw");
    QVERIFY(panel().exportTo(path));
    const std::string first = readAll(path);
    models().segmentation.paintSphere({20, 32, 32}, 12.0, 1);
    QStringList asked;
    panel().setConfirmOverwrite([&](const QString& p) {
      asked << p;
      return false;
    });
    QVERIFY(!panel().exportTo(path));
    QCOMPARE(asked, QStringList{path});
    QVERIFY(readAll(path) == first);  // untouched
    panel().setConfirmOverwrite([](const QString&) { return true; });
    QVERIFY(panel().exportTo(path));
    QVERIFY(readAll(path) != first);
#ifdef VOXRAY_HAS_SEGMENT_FILES
    // A label map on the 32-voxel phantom's grid: not this volume's.
    const Volume small = makeHeadPhantom(32);
    Segmentation other = emptySegmentation(small);
    Segment s;
    s.label = 1;
    s.name = "Other";
    other.segments.push_back(s);
    other.labels[other.grid.index(16, 16, 16)] = 1;
    const QString nifti = dir.filePath("other.nii");
    writeSegmentationNifti(nifti.toStdString(), other);
    const auto before = models().segmentation.segmentation().labels;
    QVERIFY(!panel().importFrom(nifti));
    QCOMPARE(errors_.size(), 1);
    qInfo("%s", qPrintable(errors_.first()));
    QVERIFY(errors_.first().contains("Cannot import"));
    QVERIFY(errors_.first().contains("32"));  // the other grid's size is named
    QVERIFY(models().segmentation.segmentation().labels == before);
    // This volume's own label map comes back whole.
    const QString own = dir.filePath("own.nii");
    writeSegmentationNifti(own.toStdString(), models().segmentation.segmentation());
    models().segmentation.paintSphere({40, 32, 32}, 8.0, 1);
    QVERIFY(panel().importFrom(own));
    QVERIFY(models().segmentation.segmentation().labels == before);
#endif
  }

  // Scissors: a lasso around the whole 3D image removes the segment (what lies behind it),
  // one undo step; with no segment chosen the status bar says so.
  void scissorsLassoInThe3DViewCutsOneUndoStep() {
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
    QCOMPARE(QString::fromStdString(models().segmentation.undoText()),
             QString("Undo Scissors keep"));
  }

  // From TF: the range becomes the 3D view's opaque HU range (dvr table), or iso's range
  // (both inside the 64³ phantom's values, -1000 ... 965 HU, so not clamped).
  void fromTfTakesTheTransferFunctionsOpaqueRange() {
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

  // With a segment tool chosen, Ctrl+click in the 3D view picks the segment it hits (the
  // skull, seen from the front) and the list selects it.
  void ctrlClickIn3DPicksTheSegment() {
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
  void editMenuUndoAndRedoTakeBackAPaintInTheOrderMade() {
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

  // The colour chosen in the dialog (answered through its hook) colours the overlay; opacity
  // typed in percent sets the segment's, a bad one is refused with the old kept; category and
  // type typed are free text.
  void colourDialogAndTypedOpacityAndCategoryTakeEffect() {
    const Volume& v = *models().document.volume();
    const uint8_t label = addSegment();
    QColor offered;
    panel().setColourChooser([&](const QColor& current) {
      offered = current;
      return QColor(0, 255, 0);
    });
    auto* list = panel().findChild<QTableWidget*>("segmentList");
    emit list->cellDoubleClicked(0, 1);  // the colour column
    QVERIFY(offered.isValid());
    QCOMPARE(models().segmentation.segmentation().find(label)->colour, glm::vec3(0, 1, 0));
    list->item(0, 3)->setText("80");  // opacity %
    QCOMPARE(models().segmentation.segmentation().find(label)->opacity, 0.8f);
    list->item(0, 3)->setText("lots");
    QCOMPARE(errors_.size(), 1);
    QVERIFY(errors_.first().contains("percent"));
    QCOMPARE(models().segmentation.segmentation().find(label)->opacity, 0.8f);
    QCOMPARE(list->item(0, 3)->text(), QString("80"));  // the cell shows the kept value
    list->item(0, 4)->setText("Tissue");
    list->item(0, 5)->setText("Bone");
    QCOMPARE(models().segmentation.segmentation().find(label)->category.meaning,
             std::string("Tissue"));
    QCOMPARE(models().segmentation.segmentation().find(label)->type.meaning, std::string("Bone"));
    // The overlay over a painted voxel: the chosen green at the fill's share of 80 %.
    const int slice = models().crosshair.sliceOf(axial().axes());
    glm::dvec3 target(30, 34, 0);
    target[axial().axes().nAxis] = slice;
    models().segmentation.paintDisc(axial().axes().nAxis, target, 6.0, label);
    QCoreApplication::processEvents();
    const QImage& o = axial().segmentOverlayImage();
    const glm::dvec2 s = voxelToSlice(axial().axes(), v.dims, target);
    const QColor at = o.pixelColor(int(s.x * o.width() / v.dims[axial().axes().uAxis]),
                                   int(s.y * o.height() / v.dims[axial().axes().vAxis]));
    QCOMPARE(at.red(), 0);
    QCOMPARE(at.green(), 255);
    QCOMPARE(at.blue(), 0);
    QCOMPARE(at.alpha(), int(std::lround(255 * 0.8 * kSegmentFillShare)));
  }

  // The statistics follow an edit without Update (after the debounce, counted in the
  // background), and Save CSV writes the same numbers: voxels, and mL = voxels × 64 mm³.
  void statisticsFollowEditsAndSaveCsvWritesTheNumbers() {
    const uint8_t label = addSegment();
    auto* stats = panel().findChild<QTableWidget*>("segmentStats");
    models().segmentation.paintSphere({32, 32, 32}, 12.0, label);
    const size_t n = countLabel(models().segmentation.segmentation(), label);
    QVERIFY(n > 100);  // a 12 mm ball of 4 mm voxels: about 4/3·π·3³ = 113
    QTRY_COMPARE_WITH_TIMEOUT(stats->item(0, 1) ? stats->item(0, 1)->text() : QString(),
                              QString::number(n), 5000);
    models().segmentation.eraseSphere({32, 32, 32}, 4.0, label);
    const size_t m = countLabel(models().segmentation.segmentation(), label);
    QVERIFY(m < n);
    QTRY_COMPARE_WITH_TIMEOUT(stats->item(0, 1)->text(), QString::number(m), 5000);
    QTemporaryDir dir;
    const QString path = dir.filePath("stats.csv");
    QVERIFY(panel().saveCsvTo(path));
    const QStringList lines = QString::fromStdString(readAll(path)).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2);
    QVERIFY(lines[0].startsWith("label,name,voxels,volume_mm3,volume_ml"));
    const QStringList cells = lines[1].split(',');
    QCOMPARE(cells[0], QString::number(label));
    QCOMPARE(cells[2].toULongLong(), qulonglong(m));
    const Volume& v = *models().document.volume();
    const double voxelMm3 = v.spacingMm.x * v.spacingMm.y * v.spacingMm.z;
    QCOMPARE(voxelMm3, 64.0);
    QCOMPARE(cells[3].toDouble(), m * voxelMm3);  // exact: whole numbers of mm³
    QVERIFY(std::abs(cells[4].toDouble() - m * voxelMm3 / 1000.0) < 1e-6);
  }

  // A .seg.nrrd exported from the workstation and imported again gives the same voxels,
  // names and colours (3D Slicer's segmentation file).
  void segNrrdImportGivesTheSameVoxels() {
#ifndef VOXRAY_HAS_SEGMENT_FILES
    QSKIP("This build reads no segmentation files (no teem)");
#else
    const uint8_t a = addSegment();
    const uint8_t b = addSegment();
    models().segmentation.paintSphere({24, 32, 32}, 12.0, a);
    models().segmentation.paintSphere({42, 32, 30}, 8.0, b);
    models().segmentation.setColour(b, {0.0f, 0.5f, 1.0f});
    const Segmentation before = models().segmentation.segmentation();
    QVERIFY(countLabel(before, a) > 50 && countLabel(before, b) > 20);
    QTemporaryDir dir;
    const QString path = dir.filePath("skull.seg.nrrd");
    QVERIFY(panel().exportTo(path));
    models().segmentation.reset(*models().document.volume());
    QCOMPARE(countLabel(models().segmentation.segmentation(), a), size_t(0));
    QVERIFY(panel().importFrom(path));
    const Segmentation& after = models().segmentation.segmentation();
    QVERIFY(after.labels == before.labels);
    QCOMPARE(after.segments.size(), size_t(2));
    QCOMPARE(after.find(b)->name, before.find(b)->name);
    QVERIFY(glm::length(after.find(b)->colour - glm::vec3(0.0f, 0.5f, 1.0f)) < 1e-3f);
    QVERIFY(errors_.isEmpty());
#endif
  }

  // README's docs/images/segment-skull.png (run with VOXRAY_SEGMENT_SHOT=PATH under
  // xvfb-run -s "-screen 0 1920x1080x24"): CThead with a bone segment (threshold, largest
  // island) shown in 3D and overlaid in the slice views. Skipped otherwise.
  void readmeScreenshot() {
    const QString shot = qEnvironmentVariable("VOXRAY_SEGMENT_SHOT");
    if (shot.isEmpty()) QSKIP("set VOXRAY_SEGMENT_SHOT=PATH to write the README's screenshot");
    openCtheadWithASkullSegment();
    // 3D: the segment alone, in its colour (Show only).
    panel().findChild<QComboBox*>("segmentMask3d")->setCurrentIndex(int(MaskChoice::ShowOnly));
    panel().updateStatistics();
    fixture_.window->segmentDock()->show();
    fixture_.window->segmentDock()->raise();
    QVERIFY(errors_.isEmpty());
    test::waitFullFrame(*fixture_.window);
    QTest::qWait(500);
    QVERIFY(fixture_.window->grab().save(shot));
  }

  // The README's surface figure: the same skull, its 3D display Surface (the list's 3D column),
  // the dvr hiding the skull's voxels (Hide) so that the surface shows alone.
  void readmeSurfaceScreenshot() {
    const QString shot = qEnvironmentVariable("VOXRAY_SEGMENT_SURFACE_SHOT");
    if (shot.isEmpty())
      QSKIP("set VOXRAY_SEGMENT_SURFACE_SHOT=PATH to write the README's surface screenshot");
    openCtheadWithASkullSegment();
    auto* display = panel().findChild<QComboBox*>("segmentDisplay3d");
    display->setCurrentIndex(display->findText("Surface"));
    panel().findChild<QComboBox*>("segmentMask3d")->setCurrentIndex(int(MaskChoice::Hide));
    panel().updateStatistics();
    fixture_.window->segmentDock()->show();
    fixture_.window->segmentDock()->raise();
    // The list scrolled to its 3D column.
    auto* list = panel().findChild<QTableWidget*>("segmentList");
    list->scrollToItem(list->item(0, list->columnCount() - 2), QAbstractItemView::PositionAtCenter);
    list->horizontalScrollBar()->setValue(list->horizontalScrollBar()->maximum());
    QVERIFY(errors_.isEmpty());
    // The surface variant's build and the skull's field come before its first frame: wait for
    // 10 s without a frame or a band of one (a sharp frame comes in bands).
    QSignalSpy frames(&fixture_.window->scheduler(), &RenderScheduler::frameReady);
    QSignalSpy bands(&fixture_.window->scheduler(), &RenderScheduler::bandReady);
    for (int quiet = 0; quiet < 100;) {
      const qsizetype seen = frames.size() + bands.size();
      QTest::qWait(100);
      quiet = frames.size() + bands.size() == seen ? quiet + 1 : 0;
    }
    QCoreApplication::processEvents();
    QVERIFY(fixture_.window->grab().save(shot));
  }
};

}  // namespace voxray::ui

QTEST_MAIN(voxray::ui::SegmentEditorTest)
#include "segment_editor_test.moc"
