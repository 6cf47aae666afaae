// The measuring tools through the real widgets (offscreen): a distance drawn and its end
// point dragged in a slice view, Del, the side panel's list, the export check box, and a
// distance picked on the iso surface in the 3D view, and one on dvr's first opaque points.
#include <QListWidget>

#include "measure_overlay.h"
#include "slice_view.h"
#include "volume_view.h"
#include "voxray/engine/measure.h"
#include "voxray/io/synthetic.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;
using voxray::ui::test::differingPixels;

class MeasureWidgetTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;  // started afresh for each test function

  // Widget pixel of voxel (I, J) on the axial view's slice.
  QPoint at(SliceView& view, double i, double j) {
    const Volume& v = *fixture_.models->document.volume();
    const glm::dvec2 s = voxelToSlice(view.axes(), v.dims, {i, j, 0.0});
    return view.toWidget(s.x, s.y).toPoint();
  }
  // Press, move in steps, release: QTest's own events, as a user's drag.
  void dragMouse(QWidget* w, QPoint from, QPoint to) {
    QTest::mousePress(w, Qt::LeftButton, Qt::NoModifier, from);
    for (int step = 1; step <= 4; ++step) QTest::mouseMove(w, from + (to - from) * step / 4);
    QTest::mouseRelease(w, Qt::LeftButton, Qt::NoModifier, to);
  }
  // Millimetres one widget pixel covers in the axial view (the tolerance of a mouse position).
  double mmPerPixel(SliceView& view) {
    const Volume& v = *fixture_.models->document.volume();
    return v.spacingMm.x / (view.toWidget(1, 0).x() - view.toWidget(0, 0).x());
  }

  // Ctrl+click twice on the analytic sphere (48^3, value 100 HU per voxel of depth) shown
  // with APPEARANCE: the centre of the 3D view and a point up and right of it must make one
  // 3D distance over 3 mm. Each point's depth inside the surface (voxels) goes to DEPTHS.
  void pickTwiceOnTheSphere(void (*appearance)(RenderParams&), std::vector<double>& depths) {
    const SyntheticSpec spec{SyntheticShape::Sphere, 48};
    auto v = std::make_shared<const Volume>(makeSyntheticVolume(spec));
    fixture_.models->crosshair.setDims(v->dims);
    fixture_.models->document.set(v, "sphere");
    fixture_.models->render.update(kAppearance, appearance);
    test::waitFullFrame(*fixture_.window);
    VolumeView& view = fixture_.window->volumeView();
    const QRect r = view.imageRect();
    QSignalSpy picks(&fixture_.window->scheduler(), &RenderScheduler::pickReady);
    QSignalSpy missed(&view, &VolumeView::pickMissed);
    for (QPoint click : {r.center(), r.center() + QPoint(r.width() / 16, -r.height() / 16)}) {
      QTest::mouseClick(&view, Qt::LeftButton, Qt::ControlModifier, click);
      QVERIFY(picks.wait(60000));
    }
    QVERIFY2(missed.isEmpty(), missed.isEmpty() ? "" : qPrintable(missed.first().at(0).toString()));
    QCOMPARE(int(fixture_.models->measurements.items().size()), 1);
    const Measurement& m = fixture_.models->measurements.items().front();
    QCOMPARE(m.normalAxis, -1);
    for (const auto& p : m.points) depths.push_back(AnalyticField{spec}.value(p) / 100.0);
    QVERIFY(distanceMm(*v, m.points[0], m.points[1]) > 3.0);
  }

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void distanceEndPointDragUpdatesValue() {
    SliceView& axial = fixture_.window->sliceView(0);
    const Volume& v = *fixture_.models->document.volume();
    fixture_.models->measurements.setTool(MeasureTool::Distance);
    dragMouse(&axial, at(axial, 10, 20), at(axial, 40, 20));
    QCOMPARE(int(fixture_.models->measurements.items().size()), 1);
    const Measurement& m = fixture_.models->measurements.items().front();
    const double tol = 2 * mmPerPixel(axial);  // each end within a pixel of the voxel centre
    QVERIFY2(std::abs(distanceMm(v, m.points[0], m.points[1]) - 30 * v.spacingMm.x) < tol,
             measurementText(v, m).c_str());
    const glm::dvec3 start = m.points[0];
    // Grab the end handle and drag it 30 voxels down: the distance becomes the diagonal.
    dragMouse(&axial, at(axial, 40, 20), at(axial, 40, 50));
    QCOMPARE(int(fixture_.models->measurements.items().size()), 1);
    const Measurement& moved = fixture_.models->measurements.items().front();
    QCOMPARE(moved.points[0], start);  // the other end stays
    const double diagonal = std::hypot(30 * v.spacingMm.x, 30 * v.spacingMm.y);
    const double now = distanceMm(v, moved.points[0], moved.points[1]);
    QVERIFY2(std::abs(now - diagonal) < tol, measurementText(v, moved).c_str());
    // The side panel lists the new value.
    auto* list = fixture_.window->findChild<QListWidget*>("measurementList");
    QVERIFY(list);
    QCOMPARE(list->count(), 1);
    QVERIFY2(list->item(0)->text().contains(QString::fromStdString(measurementText(v, moved))),
             qPrintable(list->item(0)->text()));
    // Del in the view removes the selected measurement.
    axial.setFocus();
    QTest::keyClick(&axial, Qt::Key_Delete);
    QCOMPARE(int(fixture_.models->measurements.items().size()), 0);
    QCOMPARE(list->count(), 0);
  }

  // Issue 41 item 9: an ROI's numbers (mean, SD, min, max, area, pixels) ran off the view's
  // right edge. Drawn at the ROI's last corner near the bottom right of a grid-sized axial
  // view, they break into lines and stay inside the view, all of them.
  void roiLabelStaysInsideTheView() {
    SliceView& axial = fixture_.window->sliceView(0);
    const Volume& v = *fixture_.models->document.volume();
    fixture_.models->measurements.setTool(MeasureTool::Ellipse);
    dragMouse(&axial, at(axial, 40, 40), at(axial, 62, 62));
    QCOMPARE(int(fixture_.models->measurements.items().size()), 1);
    const Measurement& m = fixture_.models->measurements.items().front();
    const QString text = QString::fromStdString(measurementText(v, m));
    QVERIFY2(text.startsWith("mean ") && text.endsWith(" px"), qPrintable(text));
    const QFontMetricsF fm(axial.font());
    const QRectF view(axial.rect());
    const glm::dvec2 last = voxelToSlice(axial.axes(), v.dims, m.points.back());
    const QPointF corner = axial.toWidget(last.x, last.y);  // where the view labels it
    QVERIFY2(corner.x() + 8 + fm.horizontalAdvance(text) > view.right(),
             "the one-line label would not run off: the view is too wide for this test");
    const MeasureLabel label = layoutMeasureLabel(fm, view, corner, text);
    QVERIFY2(view.contains(label.rect), qPrintable(QString("label %1,%2 %3x%4 in %5x%6")
                                                       .arg(label.rect.x())
                                                       .arg(label.rect.y())
                                                       .arg(label.rect.width())
                                                       .arg(label.rect.height())
                                                       .arg(view.width())
                                                       .arg(view.height())));
    QVERIFY(label.lines.size() >= 2);
    for (const QString& line : label.lines) QVERIFY(fm.horizontalAdvance(line) <= view.width());
    QCOMPARE(label.lines.join(" ").simplified(), text.simplified());  // every number shown
    QCOMPARE(label.rect.height(), label.lines.size() * fm.lineSpacing());

    // A short label where there is room keeps its place: right of the point, above it.
    const MeasureLabel shortLabel = layoutMeasureLabel(fm, view, QPointF(20, 40), "12.3 mm");
    QCOMPARE(shortLabel.lines, QStringList{"12.3 mm"});
    QCOMPARE(shortLabel.rect.topLeft(), QPointF(28, 34 - fm.ascent()));
  }

  void exportsShowMeasurementsOnlyWhenTicked() {
    SliceView& axial = fixture_.window->sliceView(0);
    axial.setAnnotations(false);  // no cursor readout in the comparison
    axial.setExporting(true);
    const QImage plain = axial.grab().toImage();
    fixture_.models->measurements.add(MeasureKind::Ellipse, {{20, 20, 32}, {40, 44, 32}}, 2);
    const QImage hidden = axial.grab().toImage();
    QCOMPARE(fixture_.models->measurements.showInExports(), false);  // off by default
    QCOMPARE(differingPixels(plain, hidden), 0);
    fixture_.models->measurements.setShowInExports(true);
    const QImage shown = axial.grab().toImage();
    QVERIFY(differingPixels(plain, shown) > 50);
    axial.setExporting(false);  // on screen they always show
    fixture_.models->measurements.setShowInExports(false);
    QVERIFY(differingPixels(plain, axial.grab().toImage()) > 50);
  }

  // In iso mode both picked points lie within 0.05 voxel of the surface.
  void ctrlClickPicksIsoSurfacePoints() {
    std::vector<double> depths;
    pickTwiceOnTheSphere(
        [](RenderParams& p) {
          p.mode = Mode::Iso;
          p.isoLo = 0.0;
        },
        depths);
    if (QTest::currentTestFailed()) return;
    for (double d : depths) QVERIFY2(std::abs(d) < 0.05, qPrintable(QString::number(d)));
  }

  // The same in dvr, opacity rising from 0 at the surface to 1 one voxel inside: the picks
  // are where the accumulated opacity reaches 0.5, 0.910 voxel deep along the normal and
  // shallower obliquely (tests/engine/dvr_pick_test.cpp holds them to 0.05 voxel of the
  // analytic point); a click beside the sphere says why nothing was picked.
  void ctrlClickPicksDvrOpaquePoints() {
    std::vector<double> depths;
    pickTwiceOnTheSphere(
        [](RenderParams& p) {
          p.mode = Mode::Dvr;
          p.transferFunction = {{0.0, glm::dvec4(1.0, 1.0, 1.0, 0.0)},
                                {100.0, glm::dvec4(1.0, 1.0, 1.0, 1.0)}};
        },
        depths);
    if (QTest::currentTestFailed()) return;
    for (double d : depths) QVERIFY2(d > 0.75 && d < 0.96, qPrintable(QString::number(d)));
    VolumeView& view = fixture_.window->volumeView();
    QSignalSpy picks(&fixture_.window->scheduler(), &RenderScheduler::pickReady);
    QSignalSpy missed(&view, &VolumeView::pickMissed);
    QTest::mouseClick(&view, Qt::LeftButton, Qt::ControlModifier,
                      view.imageRect().topLeft() + QPoint(2, 2));
    QVERIFY(picks.wait(60000));
    QCOMPARE(missed.size(), 1);
    QVERIFY2(missed.first().at(0).toString().contains("50 %"),
             qPrintable(missed.first().at(0).toString()));
    QCOMPARE(int(fixture_.models->measurements.items().size()), 1);
    QVERIFY(!fixture_.models->measurements.pendingPick());
  }
};

QTEST_MAIN(MeasureWidgetTest)
#include "measure_widget_test.moc"
