// The slice views' interpolation: the Slices panel's toggle switches the coronal view of
// thick slices between blocks (nearest) and a ramp (trilinear), at the physical aspect.
// Oblique and thick-slab MPR: a crosshair handle dragged by a known angle turns the other
// planes by it, the panel's slab settings and reset drive the views, and the views show
// what the models' planes say, pixel for pixel (a slab once its background render arrives).
#include <cmath>
#include <set>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>

#include "qt_image.h"
#include "slice_image.h"
#include "slice_view.h"
#include "study_state.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

constexpr int kSliceCount = 8;

// 32 x 32 columns of 1 mm pixels, 8 slices of 5 mm; each slice 100 HU above the one below.
std::shared_ptr<const Volume> thickSliceCount() {
  auto v = std::make_shared<Volume>();
  v->dims = {32, 32, kSliceCount};
  v->spacingMm = {1.0, 1.0, 5.0};
  v->modality = "CT";
  v->voxels.resize(v->voxelCount());
  for (int k = 0; k < kSliceCount; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) v->voxels[v->index(i, j, k)] = int16_t(100 * k);
  return v;
}

// The grey values down the image's middle column, top to bottom.
std::vector<int> middleColumn(const QImage& img) {
  std::vector<int> out;
  for (int y = 0; y < img.height(); ++y) out.push_back(qGray(img.pixel(img.width() / 2, y)));
  return out;
}

constexpr double kDeg = M_PI / 180.0;

void send(QWidget* w, QEvent::Type type, QPointF at, Qt::MouseButton b, Qt::MouseButtons held) {
  QMouseEvent e(type, at, w->mapToGlobal(at), b, held, Qt::NoModifier);
  QApplication::sendEvent(w, &e);
}

// What the view should show for the models' current state.
QImage expectedImage(const AppModels& m, const SliceView& view) {
  const Volume& v = *m.document.volume();
  const Orientation o = view.orientation();
  return toQImage(
      renderPlane(v, viewPlane(v, view.axes(), m.crosshair.centre(), m.crosshair.rotation(o)),
                  m.windowLevel.value(), m.render.sliceInterp(), m.crosshair.slab(o)));
}

}  // namespace

class SliceInterpTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void toggleTurnsThickSliceStairsIntoARamp() {
    AppModels& m = *fixture_.models;
    openStudy(m, thickSliceCount(), "thick slices");
    m.windowLevel.set({800.0, 350.0});  // 0 ... 700 HU spread over the grey range
    auto* toggle = fixture_.window->findChild<QCheckBox*>("sliceInterp");
    QVERIFY(toggle);
    QVERIFY(toggle->isChecked());  // trilinear by default
    SliceView& coronal = fixture_.window->sliceView(1);
    // The physical aspect: 32 mm wide, 40 mm high in 1 mm pixels.
    QCOMPARE(coronal.sliceImage().size(), QSize(32, 40));
    const std::vector<int> linear = middleColumn(coronal.sliceImage());

    toggle->setChecked(false);
    QCOMPARE(m.render.sliceInterp(), Interp::Nearest);
    const std::vector<int> nearest = middleColumn(coronal.sliceImage());
    QCOMPARE(int(nearest.size()), 40);
    // Nearest: one grey per slice, each held for 5 rows (superior, the highest, on top).
    QCOMPARE(int(std::set<int>(nearest.begin(), nearest.end()).size()), kSliceCount);
    for (int y = 0; y < 40; ++y) {
      const int slice = kSliceCount - 1 - y / 5;
      QCOMPARE(nearest[size_t(y)], int(mapToGrey(100.0 * slice, m.windowLevel.value())));
    }
    // Trilinear: a ramp between slice centres, falling by 100 HU every 5 rows; the rows
    // at the slice centres (y = 2, 7, ...) keep the slice's own value.
    for (int y = 3; y < 37; ++y) {
      const double hu = 100.0 * ((kSliceCount - 1) - (y - 2) / 5.0);
      QCOMPARE(linear[size_t(y)], int(mapToGrey(hu, m.windowLevel.value())));
    }
    QVERIFY(std::set<int>(linear.begin(), linear.end()).size() > 30);
    QVERIFY(linear != nearest);

    toggle->setChecked(true);
    QCOMPARE(m.render.sliceInterp(), Interp::Linear);
    QCOMPARE(middleColumn(coronal.sliceImage()), linear);
  }

  void handleDragTurnsTheOtherPlanesByTheAngle() {
    AppModels& m = *fixture_.models;
    SliceView& axial = fixture_.window->sliceView(0);
    SliceView& coronal = fixture_.window->sliceView(1);
    const QImage coronalBefore = coronal.sliceImage();
    // The first handle sits on the upright line (the sagittal plane's trace) above the centre.
    const auto handles = axial.rotationHandles();
    const glm::dvec2 c = voxelToSlice(axial.axes(), m.crosshair.dims(), m.crosshair.centre());
    const QPointF centre = axial.toWidget(c.x, c.y);
    const QPointF from = handles[0];
    QVERIFY(from.y() < centre.y() - 20);
    QCOMPARE(from.x(), centre.x());
    // Swept 30 degrees clockwise about the centre, in 10 steps along the arc.
    const double radius = QLineF(centre, from).length();
    send(&axial, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    QPointF to;
    for (int i = 1; i <= 10; ++i) {
      const double a = -M_PI / 2 + 30 * kDeg * i / 10.0;  // y down: clockwise is +angle
      to = centre + QPointF(std::cos(a), std::sin(a)) * radius;
      send(&axial, QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    }
    send(&axial, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    // The sagittal normal (L) turned towards P by 30 degrees, about the axial normal (S);
    // the centre did not move. Float mouse positions: 1e-6 of the angle.
    const SliceAxes sagittal = fixture_.window->sliceView(2).axes();
    const glm::dvec3 n = m.crosshair.frame(sagittal).normal;
    QVERIFY2(std::abs(std::atan2(n.y, n.x) - 30 * kDeg) < 1e-6, qPrintable(QString::number(n.y)));
    QVERIFY(std::abs(n.z) < 1e-12);
    QCOMPARE(m.crosshair.frame(axial.axes()).normal, glm::dvec3(0, 0, 1));
    QCOMPARE(m.crosshair.centre(), glm::dvec3(m.crosshair.dims() / 2));
    // The coronal view shows the turned plane; the axial view's lines lean by 30 degrees.
    QCOMPARE(coronal.sliceImage(), expectedImage(m, coronal));
    QVERIFY(coronal.sliceImage() != coronalBefore);
    const glm::dvec2 upright = axial.crosshairTraces()[0];
    QVERIFY(std::abs(std::abs(std::atan2(upright.x, upright.y)) - 30 * kDeg) < 1e-6);
    // The drag is one undo step: Edit > Undo turns the planes back at once, exactly.
    fixture_.window->history().undo();
    QCOMPARE(m.crosshair.frame(sagittal).normal, glm::dvec3(1, 0, 0));
    QVERIFY(!m.crosshair.rotated());
    QVERIFY(!fixture_.window->history().canUndo());
    QCOMPARE(coronal.sliceImage(), coronalBefore);
  }

  void panelSlabAndResetDriveTheViews() {
    AppModels& m = *fixture_.models;
    SliceView& axial = fixture_.window->sliceView(0);
    const QImage thin = axial.sliceImage();
    auto* thickness = fixture_.window->findChild<QDoubleSpinBox*>("slab_axial");
    auto* mode = fixture_.window->findChild<QComboBox*>("slabMode_axial");
    auto* reset = fixture_.window->findChild<QPushButton*>("resetPlanes");
    QVERIFY(thickness && mode && reset);
    QVERIFY(!reset->isEnabled());  // nothing turned
    thickness->setValue(20.0);
    mode->setCurrentIndex(int(SlabMode::MinIp));
    QCOMPARE(m.crosshair.slab(Orientation::Axial).thicknessMm, 20.0);
    QCOMPARE(m.crosshair.slab(Orientation::Axial).mode, SlabMode::MinIp);
    // The slab renders in the background: both changes returned before any slab image, the
    // thin slice stands in, and the image that arrives is the newest request's (MinIP).
    QVERIFY(axial.slabPending());
    QCOMPARE(axial.sliceImage(), thin);
    QTRY_VERIFY_WITH_TIMEOUT(!axial.slabPending(), 30000);
    QCOMPARE(axial.sliceImage(), expectedImage(m, axial));
    QVERIFY(axial.sliceImage() != thin);
    QTest::qWait(200);  // a stale MIP image arriving late would replace it: none does
    QCOMPARE(axial.sliceImage(), expectedImage(m, axial));
    thickness->setValue(0.0);  // thin again: today's slice
    QCOMPARE(axial.sliceImage(), thin);

    m.crosshair.rotateInView(axial.axes(), 20 * kDeg);
    QVERIFY(reset->isEnabled());
    reset->click();
    QVERIFY(!m.crosshair.rotated());
    m.crosshair.rotateInView(axial.axes(), -15 * kDeg);
    fixture_.window->activateWindow();
    QTest::keyClick(fixture_.window.get(), Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(!m.crosshair.rotated());
    SliceView& sagittal = fixture_.window->sliceView(2);
    const Volume& v = *m.document.volume();
    QCOMPARE(sagittal.sliceImage(),
             toQImage(renderSlice(v, sagittal.axes(), m.crosshair.sliceOf(sagittal.axes()),
                                  m.windowLevel.value(), m.render.sliceInterp())));
  }
};

QTEST_MAIN(SliceInterpTest)
#include "slice_interp_test.moc"
