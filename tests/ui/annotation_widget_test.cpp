// Issue 37: text and arrow annotations through the real widgets (offscreen): an arrow dragged
// by known pixels lands at the millimetres the view's pixel mapping gives and is drawn in the
// annotation colour at its head; a text click types into a line edit; the Measurements panel
// lists and deletes them; Edit > Undo takes a step back; exports show them only when ticked.
#include <QAction>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>

#include "annotation_overlay.h"
#include "slice_view.h"
#include "voxray/engine/measure.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;
using voxray::ui::test::differingPixels;

class AnnotationWidgetTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;  // started afresh for each test function

  // Widget pixel of voxel (I, J) on the axial view's slice.
  QPoint at(SliceView& view, double i, double j) {
    const Volume& v = *fixture_.models->document.volume();
    const glm::dvec2 s = voxelToSlice(view.axes(), v.dims, {i, j, 0.0});
    return view.toWidget(s.x, s.y).toPoint();
  }
  // The patient position (LPS mm) the view shows at widget pixel P: its own pixel-to-slice
  // mapping, the slice's voxel, and the volume's geometry.
  glm::dvec3 mmAt(SliceView& view, QPoint p) {
    const Volume& v = *fixture_.models->document.volume();
    const glm::dvec2 s = view.toSlice(QPointF(p));
    const int slice = fixture_.models->crosshair.sliceOf(view.axes());
    return voxelToPatient(v, sliceToVoxel(view.axes(), v.dims, s.x, s.y, slice));
  }
  void dragMouse(QWidget* w, QPoint from, QPoint to) {
    QTest::mousePress(w, Qt::LeftButton, Qt::NoModifier, from);
    for (int step = 1; step <= 4; ++step) QTest::mouseMove(w, from + (to - from) * step / 4);
    QTest::mouseRelease(w, Qt::LeftButton, Qt::NoModifier, to);
  }
  static QString rgb(QColor c) {
    return QString("%1,%2,%3").arg(c.red()).arg(c.green()).arg(c.blue());
  }

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void arrowDragLandsInMillimetresAndIsDrawnAtItsHead() {
    SliceView& axial = fixture_.window->sliceView(0);
    const Volume& v = *fixture_.models->document.volume();
    axial.setAnnotations(false);  // no cursor readout over the pixels checked
    fixture_.models->measurements.setTool(MeasureTool::Arrow);
    // Both inside the volume (a drag past its edge is held at the edge).
    const QPoint head = at(axial, 20, 24), tail = at(axial, 44, 34);
    const int dx = tail.x() - head.x(), dy = tail.y() - head.y();
    QVERIFY(dx > 20 && dy > 10);
    dragMouse(&axial, head, tail);
    const auto& items = fixture_.models->annotations.items();
    QCOMPARE(int(items.size()), 1);
    const Annotation& a = items.front();
    QVERIFY(a.isArrow());
    QCOMPARE(int(fixture_.models->measurements.items().size()), 0);  // no measurement made
    // The points are the view's own mapping of the press and release pixels (to rounding).
    QVERIFY(glm::distance(a.anchorMm, mmAt(axial, head)) < 1e-9);
    QVERIFY(glm::distance(*a.tailMm, mmAt(axial, tail)) < 1e-9);
    // And in millimetres: the axial view shows i to the right and j down (identity directions:
    // L and P), so DX and DY pixels are that many times the view's mm per pixel. The two
    // lie in the slice's plane, whose S is the crosshair's slice.
    const double mmPerPixel = v.spacingMm.x / (axial.toWidget(1, 0).x() - axial.toWidget(0, 0).x());
    const glm::dvec3 d = *a.tailMm - a.anchorMm;
    QVERIFY2(std::abs(d.x - dx * mmPerPixel) < 1e-6, qPrintable(QString::number(d.x)));
    QVERIFY2(std::abs(d.y - dy * mmPerPixel) < 1e-6, qPrintable(QString::number(d.y)));
    QCOMPARE(d.z, 0.0);
    const int slice = fixture_.models->crosshair.sliceOf(axial.axes());
    QVERIFY(std::abs(a.anchorMm.z - voxelToPatient(v, {0, 0, double(slice)}).z) < 1e-9);
    QVERIFY(glm::distance(a.normal, glm::dvec3(0, 0, 1)) < 1e-12);

    // Drawn: the pixel just inside the arrowhead's tip (3 px back along the shaft, clear of
    // the tip's antialiased edge) has the annotation colour, selected and then not.
    const QPointF u = QPointF(tail - head) / std::hypot(double(dx), double(dy));
    const QPoint inside = (QPointF(head) + 3.0 * u).toPoint();
    QColor got = axial.grab().toImage().pixelColor(inside);
    QVERIFY2(got.rgb() == kAnnotationSelectedColor.rgb(), qPrintable(rgb(got)));
    fixture_.models->annotations.select(0);
    got = axial.grab().toImage().pixelColor(inside);
    QVERIFY2(got.rgb() == kAnnotationColor.rgb(), qPrintable(rgb(got)));
    // Not on the next slice: it belongs to the plane it was drawn on.
    fixture_.models->crosshair.scrollView(axial.axes(), 2);
    got = axial.grab().toImage().pixelColor(inside);
    QVERIFY2(got.rgb() != kAnnotationColor.rgb(), qPrintable(rgb(got)));

    // A click without a drag makes no arrow.
    fixture_.models->crosshair.scrollView(axial.axes(), -2);
    QTest::mouseClick(&axial, Qt::LeftButton, Qt::NoModifier, at(axial, 40, 40));
    QCOMPARE(int(items.size()), 1);
  }

  void textClickTypesListsDeletesAndUndoes() {
    SliceView& axial = fixture_.window->sliceView(0);
    fixture_.models->measurements.setTool(MeasureTool::Text);
    const QPoint p = at(axial, 30, 30);
    QTest::mouseClick(&axial, Qt::LeftButton, Qt::NoModifier, p);
    auto* edit = qobject_cast<QLineEdit*>(axial.annotationEditor());
    QVERIFY(edit);
    QCOMPARE(edit->pos(), p);  // where the click was
    QTest::keyClicks(edit, "Lesion 1");
    QTest::keyClick(edit, Qt::Key_Return);
    QVERIFY(!axial.annotationEditor());
    const auto& items = fixture_.models->annotations.items();
    QCOMPARE(int(items.size()), 1);
    QCOMPARE(QString::fromStdString(items[0].text), QString("Lesion 1"));
    QVERIFY(!items[0].isArrow());
    QVERIFY(glm::distance(items[0].anchorMm, mmAt(axial, p)) < 1e-9);

    // Esc drops a second one.
    QTest::mouseClick(&axial, Qt::LeftButton, Qt::NoModifier, at(axial, 10, 10));
    edit = qobject_cast<QLineEdit*>(axial.annotationEditor());
    QVERIFY(edit);
    QTest::keyClicks(edit, "dropped");
    QTest::keyClick(edit, Qt::Key_Escape);
    QVERIFY(!axial.annotationEditor());
    QCOMPARE(int(items.size()), 1);

    // The panel lists it; its Delete removes it; Edit > Undo brings it back.
    auto* list = fixture_.window->findChild<QListWidget*>("annotationList");
    QVERIFY(list);
    QCOMPARE(list->count(), 1);
    QCOMPARE(list->item(0)->text(), QString("text  Lesion 1"));
    list->setCurrentRow(0);
    auto* remove = fixture_.window->findChild<QPushButton*>("annotationDelete");
    QVERIFY(remove && remove->isEnabled());
    remove->click();
    QCOMPARE(int(items.size()), 0);
    QCOMPARE(list->count(), 0);
    auto* undo = fixture_.window->findChild<QAction*>("editUndo");
    QVERIFY(undo && undo->isEnabled());
    QCOMPARE(undo->toolTip(), QString("Undo Delete annotation"));
    undo->trigger();
    QCOMPARE(int(items.size()), 1);
    QCOMPARE(list->count(), 1);
    // Del in the view removes the selected one.
    fixture_.models->annotations.select(items[0].id);
    axial.setFocus();
    QTest::keyClick(&axial, Qt::Key_Delete);
    QCOMPARE(int(items.size()), 0);
  }

  void exportsShowAnnotationsOnlyWhenTicked() {
    SliceView& axial = fixture_.window->sliceView(0);
    const Volume& v = *fixture_.models->document.volume();
    axial.setAnnotations(false);
    axial.setExporting(true);
    const QImage plain = axial.grab().toImage();
    const int slice = fixture_.models->crosshair.sliceOf(axial.axes());
    fixture_.models->annotations.addArrow(voxelToPatient(v, {20, 20, double(slice)}),
                                          voxelToPatient(v, {40, 44, double(slice)}),
                                          sliceNormal(v, axial.axes()), "here");
    QCOMPARE(differingPixels(plain, axial.grab().toImage()), 0);
    fixture_.models->measurements.setShowInExports(true);
    QVERIFY(differingPixels(plain, axial.grab().toImage()) > 50);
    axial.setExporting(false);  // on screen they always show
    fixture_.models->measurements.setShowInExports(false);
    QVERIFY(differingPixels(plain, axial.grab().toImage()) > 50);
  }

  // docs/images/annotations.png: the Philips head CT with two arrows and a text on slice 14.
  void readmeScreenshot() {
    const QString shot = qEnvironmentVariable("VOXRAY_ANNOTATION_SHOT");
    if (shot.isEmpty()) QSKIP("set VOXRAY_ANNOTATION_SHOT=PATH to write the README's screenshot");
    MainWindow& window = *fixture_.window;
    window.resize(1600, 1000);
    QSignalSpy shown(&window, &MainWindow::volumeShown);
    window.open(VOXRAY_DATA_DIR "/dicom/ct-philips-phantom/S2010", {});
    QVERIFY(shown.wait(120000));
    const Volume& v = *fixture_.models->document.volume();
    fixture_.models->crosshair.setVoxel({256, 256, 14});
    const SliceAxes& axes = window.sliceView(0).axes();
    const glm::dvec3 n = sliceNormal(v, axes);
    auto mm = [&](double i, double j) { return voxelToPatient(v, {i, j, 14.0}); };
    auto& a = fixture_.models->annotations;
    a.addArrow(mm(170, 250), mm(80, 120), n, "check this insert");
    a.addText("phantom centre", mm(262, 262), n);
    a.addArrow(mm(340, 330), mm(430, 430), n);
    a.select(0);
    test::waitFullFrame(window);
    QTest::qWait(500);
    QVERIFY(window.grab().save(shot));
  }
};

QTEST_MAIN(AnnotationWidgetTest)
#include "annotation_widget_test.moc"
