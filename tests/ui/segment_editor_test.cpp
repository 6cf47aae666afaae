// The segment editor tests' fixture (segment_editor_test.h): a window on the head phantom for
// each test, the helpers the tests share, and the README's figures.
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

size_t countLabel(const Segmentation& s, uint8_t label) {
  size_t n = 0;
  for (uint8_t l : s.labels) n += l == label;
  return n;
}

std::string readAll(const QString& path) {
  std::ifstream in(path.toStdString(), std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

int litPixels(const QImage& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += (image.pixel(x, y) & 0xffffff) != 0;
  return n;
}

void SegmentEditorTest::setTool(const std::function<void(SegmentToolSettings&)>& edit) {
  SegmentToolSettings s = models().segmentTools.settings();
  edit(s);
  models().segmentTools.set(s);
}

QPoint SegmentEditorTest::widgetOf(glm::dvec3 voxel) {
  const glm::dvec2 s = voxelToSlice(axial().axes(), models().document.volume()->dims, voxel);
  return axial().toWidget(s.x, s.y).toPoint();
}

glm::dvec3 SegmentEditorTest::voxelAt(QPoint p) {
  const glm::dvec2 s = axial().toSlice(QPointF(p));
  return models().crosshair.viewToVoxel(axial().axes(), s.x, s.y);
}

uint8_t SegmentEditorTest::addSegment() {
  fixture_.window->segmentDock()->show();
  auto* add = panel().findChild<QPushButton*>("segmentAdd");
  add->click();
  return panel().currentLabel();
}

SegmentEditorTest::SegmentChange SegmentEditorTest::changeWhereTheSegmentShows(
    const QImage& before, const QImage& after, const QImage& showA, const QImage& showB) {
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

void SegmentEditorTest::openCtheadWithASkullSegment() {
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

void SegmentEditorTest::init() {
  QVERIFY(fixture_.start());
  errors_.clear();
  fixture_.window->setErrorSink(
      [this](const QString& t, const QString& m) { errors_ << t + ": " + m; });
}

void SegmentEditorTest::cleanup() { fixture_.stop(); }

// README's docs/images/segment-skull.png (run with VOXRAY_SEGMENT_SHOT=PATH under
// xvfb-run -s "-screen 0 1920x1080x24"): CThead with a bone segment (threshold, largest
// island) shown in 3D and overlaid in the slice views. Skipped otherwise.
void SegmentEditorTest::readmeScreenshot() {
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
void SegmentEditorTest::readmeSurfaceScreenshot() {
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

}  // namespace voxray::ui

QTEST_MAIN(voxray::ui::SegmentEditorTest)
