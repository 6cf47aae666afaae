// QTest on the offscreen platform, issue 35: the transfer-function editor's preset gallery and
// its zoomable axes. The gallery shows every dvr preset (built-in and the user's folder) as a
// picture rendered from the open volume on the render thread; bone and skin look different;
// a click applies a preset as one undo step that Ctrl+Z takes back; a new volume renders the
// pictures again and the old volume's come back from the cache. After a zoom of the HU axis a
// point dragged by N pixels moves by N times the HU a pixel is worth at that zoom; the 2D
// histogram's axes zoom one at a time.
#include <QAction>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include "axis_zoom.h"
#include "tf_editor_dialog.h"
#include "voxray/io/histogram.h"
#include "voxray/io/raw_import.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

TfEditorDialog* openEditor(MainWindow& window, int tab) {
  auto* action = window.findChild<QAction*>("viewTfEditor");
  if (!action) return nullptr;
  action->trigger();
  auto* editor = window.findChild<TfEditorDialog*>("tfEditor");
  if (editor) editor->tabs().setCurrentIndex(tab);
  return editor;
}

int tileOf(TfGalleryView& g, const std::string& name) {
  for (int i = 0; i < g.tileCount(); ++i)
    if (g.model().presets()[size_t(i)].name == name) return i;
  return -1;
}

bool allRendered(TfGalleryView& g) {
  for (int i = 0; i < g.tileCount(); ++i)
    if (g.tileImage(i).isNull()) return false;
  return true;
}

void wheel(QWidget& w, QPointF at, int notches, Qt::KeyboardModifiers mods = {}) {
  QWheelEvent e(at, w.mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, mods,
                Qt::NoScrollPhase, false);
  QApplication::sendEvent(&w, &e);
}

}  // namespace

class TfGalleryTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void galleryRendersEveryPresetAndAClickIsOneUndoStep() {
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    models.render.applyPreset("CT-Bone");
    TfEditorDialog* editor = openEditor(window, 2);
    QVERIFY(editor);
    QVERIFY(QTest::qWaitForWindowExposed(editor));
    TfGalleryView& gallery = editor->gallery();
    // The user's folder: one preset of theirs beside the four built-in dvr presets.
    QTemporaryDir dir;
    VolumeProperty mine = volumePropertyOf(models.render.params());
    mine.name = "Mine";
    mine.opacity.back().opacity = 0.05;
    writeVolumePropertyFile(mine, dir.filePath("mine.json").toStdString());
    editor->usePresetFolder(dir.path());
    QCOMPARE(gallery.tileCount(), 5);
    QVERIFY(gallery.problems().isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(allRendered(gallery), 120000);

    // 96 x 96 pictures of the phantom: CT-Bone and CT-Skin colour the head differently, so
    // most of the pixels the head covers differ (the background and outline they share).
    const int bone = tileOf(gallery, "CT-Bone"), skin = tileOf(gallery, "CT-Skin");
    QVERIFY(bone >= 0 && skin >= 0);
    const QImage bonePicture = gallery.tileImage(bone), skinPicture = gallery.tileImage(skin);
    QCOMPARE(bonePicture.size(), QSize(96, 96));
    int head = 0;
    for (int y = 0; y < 96; ++y)
      for (int x = 0; x < 96; ++x) head += (bonePicture.pixel(x, y) & 0xffffff) != 0;
    const int differ = test::differingPixels(bonePicture, skinPicture);
    QVERIFY2(head > 96 * 96 / 10 && differ > head / 2,
             qPrintable(QString("%1 of %2 head pixels differ").arg(differ).arg(head)));
    QCOMPARE(gallery.tileImage(bone).size(), gallery.tileRect(bone).size());

    // A click on CT-Skin: the 3D view's table is CT-Skin's (one value checked: its last
    // point's opacity), as one undo step that Ctrl+Z in the editor takes back.
    const std::vector<ControlPoint> before = models.render.params().transferFunction.empty()
                                                 ? findPreset("CT-Bone").tf.points
                                                 : models.render.params().transferFunction;
    const std::vector<ControlPoint>& skinTable = findPreset("CT-Skin").tf.points;
    QVERIFY(before != skinTable);
    QTest::mouseClick(&gallery, Qt::LeftButton, {}, gallery.tileRect(skin).center());
    const std::vector<ControlPoint>& now = models.render.params().transferFunction;
    QCOMPARE(now, skinTable);
    QCOMPARE(now.back().rgba.a, skinTable.back().rgba.a);
    QVERIFY(editor->model().canUndo());
    editor->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(editor));
    QTest::keyClick(editor, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(models.render.params().transferFunction, before);
    QVERIFY(!editor->model().canUndo());

    // Another volume: every picture renders again; back to the first, its pictures at once.
    const std::shared_ptr<const Volume> first = models.document.volume();
    auto small = std::make_shared<const Volume>(makeHeadPhantom(40));
    models.crosshair.setDims(small->dims);
    models.document.set(small, "small");
    QCOMPARE(gallery.model().staleCount(), size_t(5));
    QTRY_VERIFY_WITH_TIMEOUT(allRendered(gallery), 120000);
    QVERIFY(test::differingPixels(gallery.tileImage(bone), bonePicture) > 0);
    models.crosshair.setDims(first->dims);
    models.document.set(first, "phantom");
    QCOMPARE(gallery.model().staleCount(), size_t(0));
    QCOMPARE(test::differingPixels(gallery.tileImage(bone), bonePicture), 0);
  }

  void zoomedHuAxisDragMovesByThePixelsWorth() {
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    models.render.applyPreset("CT-Bone");
    TfEditorDialog* editor = openEditor(window, 0);
    QVERIFY(editor);
    QVERIFY(QTest::qWaitForWindowExposed(editor));
    TfCurveView& curve = editor->curve();
    curve.setHuRange(-1000.0, 2000.0);
    const double wide = curve.huPerPixel();

    // Three notches over the HU axis at the pixel of -500 HU: the span is 0.8^3 of what it
    // was and -500 HU stays under the cursor (1e-9: floating point of a linear map).
    const QPointF at(curve.xOf(-500.0), curve.axisStrip().center().y());
    wheel(curve, at, 3);
    QVERIFY(std::abs(curve.huAt(at.x()) + 500.0) < 1e-9);
    QVERIFY(std::abs(curve.huPerPixel() - 0.512 * wide) < 1e-12);
    auto* huLo = editor->findChild<QDoubleSpinBox*>("tfHuLo");
    QVERIFY(huLo);
    QCOMPARE(huLo->value(), std::round(curve.huLo() * 10.0) / 10.0);  // the field follows
    // Ctrl+wheel over the curve zooms the same way.
    const double perPixel3 = curve.huPerPixel();
    wheel(curve, curve.curveArea().center(), 1, Qt::ControlModifier);
    QVERIFY(std::abs(curve.huPerPixel() - 0.8 * perPixel3) < 1e-12);
    wheel(curve, curve.curveArea().center(), -1, Qt::ControlModifier);

    // A point added at a whole pixel and dragged by N = 20 pixels moves by 20 pixels' worth.
    const int px = int(std::lround(curve.xOf(-500.0))), py = int(std::lround(curve.yOf(0.5)));
    QTest::mouseClick(&curve, Qt::LeftButton, {}, QPoint(px, py));
    const size_t i = curve.selection()->index;
    const double start = editor->model().property().opacity[i].x;
    QVERIFY(std::abs(start - curve.huAt(px)) < 1e-9);
    QTest::mousePress(&curve, Qt::LeftButton, {}, QPoint(px, py));
    QTest::mouseMove(&curve, QPoint(px + 10, py));
    QTest::mouseMove(&curve, QPoint(px + 20, py));
    QTest::mouseRelease(&curve, Qt::LeftButton, {}, QPoint(px + 20, py));
    const double moved = editor->model().property().opacity[i].x - start;
    QVERIFY2(std::abs(moved - 20.0 * curve.huPerPixel()) < 1e-9,
             qPrintable(QString("%1 vs %2").arg(moved).arg(20.0 * curve.huPerPixel())));
    QVERIFY(std::abs(moved - 20.0 * wide) > 10.0);  // not the unzoomed pixels' worth

    // A drag along the axis pans: what was under pixel x is under x + 30.
    const double lo = curve.huLo();
    const QPoint on = curve.axisStrip().center().toPoint();
    QTest::mousePress(&curve, Qt::LeftButton, {}, on);
    QTest::mouseMove(&curve, on + QPoint(30, 0));
    QTest::mouseRelease(&curve, Qt::LeftButton, {}, on + QPoint(30, 0));
    QVERIFY(std::abs(curve.huLo() - (lo - 30.0 * curve.huPerPixel())) < 1e-9);

    // Fit to visible: the HU that hold voxels (the phantom's air at -1000 ... its densest
    // bone), from the histogram; Reset: the volume's whole range.
    QTRY_VERIFY_WITH_TIMEOUT(editor->histogramReady(), 20000);
    editor->findChild<QPushButton*>("tfFitVisible")->click();
    const std::shared_ptr<const Volume> v = models.document.volume();
    const AxisRange visible = visibleHuRange(storedHistogram(*v), v->slope, v->intercept);
    QCOMPARE(curve.huLo(), visible.lo);
    QCOMPARE(curve.huHi(), visible.hi);
    QVERIFY(visible.lo <= -1000.0 && visible.hi > 0.0);
    editor->findChild<QPushButton*>("tfFitVolume")->click();
    QCOMPARE(curve.huLo(), -1000.0);
  }

  void histogram2dAxesZoomOneAtATime() {
    TfEditorDialog* editor = openEditor(*fixture_.window, 1);
    QVERIFY(editor);
    QTRY_VERIFY_WITH_TIMEOUT(editor->tf2dHistogramReady(), 20000);
    QVERIFY(QTest::qWaitForWindowExposed(editor));
    Tf2dView& view = editor->tf2d();
    const double huSpan = view.huHi() - view.huLo(), gSpan = view.gradientTop() - view.gradientLo();
    const QRectF a = view.plotArea();

    // Over the HU strip: only HU, about the cursor's HU.
    const QPointF onHu(a.left() + 0.3 * a.width(), view.huStrip().center().y());
    const double hu = view.huAt(onHu.x());
    wheel(view, onHu, 2);
    QVERIFY(std::abs((view.huHi() - view.huLo()) - 0.64 * huSpan) < 1e-9);
    QVERIFY(std::abs(view.huAt(onHu.x()) - hu) < 1e-9);
    QCOMPARE(view.gradientTop() - view.gradientLo(), gSpan);
    // Over the gradient strip: only |gradient|.
    const QPointF onG(view.gradientStrip().center().x(), a.top() + 0.25 * a.height());
    const double g = view.gAt(onG.y());
    wheel(view, onG, 1);
    QVERIFY(std::abs((view.gradientTop() - view.gradientLo()) - 0.8 * gSpan) < 1e-9);
    QVERIFY(std::abs(view.gAt(onG.y()) - g) < 1e-9);
    QVERIFY(std::abs((view.huHi() - view.huLo()) - 0.64 * huSpan) < 1e-9);

    // At this zoom a rectangle dragged by (+25, -15) pixels moves by their worth.
    std::unique_ptr<QMenu> menu(view.menuAt(a.center()));
    menu->findChild<QAction*>("tf2dAddRect")->trigger();
    const Tf2dPrimitive added = editor->model().property().tf2d.primitives[0];
    const double huPerPixel = (view.huHi() - view.huLo()) / a.width();
    const double gPerPixel = (view.gradientTop() - view.gradientLo()) / a.height();
    const QPoint from = a.center().toPoint() + QPoint(2, 2), to = from + QPoint(25, -15);
    QTest::mousePress(&view, Qt::LeftButton, {}, from);
    QTest::mouseMove(&view, to);
    QTest::mouseRelease(&view, Qt::LeftButton, {}, to);
    const Tf2dPrimitive moved = editor->model().property().tf2d.primitives[0];
    QVERIFY(std::abs(moved.hu0 - (added.hu0 + 25.0 * huPerPixel)) < 1e-9);
    QVERIFY(std::abs(moved.g1 - (added.g1 + 15.0 * gPerPixel)) < 1e-9);

    // Reset: the histogram's whole axes again.
    editor->findChild<QPushButton*>("tf2dReset")->click();
    QCOMPARE(view.huHi() - view.huLo(), huSpan);
    QCOMPARE(view.gradientLo(), 0.0);
  }

  // The README's figure and figures (not run by ctest): the gallery on the cranium CT with two
  // presets of the user's beside the built-in ones, the time until every picture is there and
  // each picture's render time.
  void figureGalleryOnCranium() {
    const QString out = qEnvironmentVariable("VOXRAY_FIGURE_DIR");
    if (out.isEmpty()) QSKIP("set VOXRAY_FIGURE_DIR to write the figure");
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    RawLayout layout;
    layout.dims = {256, 256, 108};
    layout.spacingMm = {0.957, 0.957, 1.5};
    auto v = std::make_shared<const Volume>(importRaw(
        std::string(VOXRAY_DATA_DIR) + "/raw/cranium-ct/cranium_256x256x108_s16le.raw", layout));
    models.crosshair.setDims(v->dims);
    models.document.set(v, "cranium");
    models.render.applyPreset("CT-Bone");
    test::waitFullFrame(window);
    QTemporaryDir dir;
    VolumeProperty soft = volumePropertyOf(models.render.params());
    soft.name = "Bone, faint";
    for (OpacityNode& o : soft.opacity) o.opacity *= 0.25;
    writeVolumePropertyFile(soft, dir.filePath("bone-faint.json").toStdString());
    VolumeProperty warm = soft;
    warm.name = "Warm skin";
    warm.opacity = {{-700.0, 0.0}, {-300.0, 0.08}, {100.0, 0.02}, {300.0, 0.6}};
    warm.color = {{-700.0, {0.8, 0.4, 0.3}}, {0.0, {0.95, 0.75, 0.6}}, {300.0, {1.0, 1.0, 0.95}}};
    writeVolumePropertyFile(warm, dir.filePath("warm-skin.json").toStdString());
    std::vector<double> ms;
    connect(&window.scheduler(), &RenderScheduler::backgroundReady, this,
            [&](std::shared_ptr<const Frame> f) { ms.push_back(f->stats.totalMs); });
    QElapsedTimer clock;
    clock.start();
    TfEditorDialog* editor = openEditor(window, 2);
    QVERIFY(editor);
    editor->usePresetFolder(dir.path());
    editor->resize(560, 420);
    TfGalleryView& gallery = editor->gallery();
    QCOMPARE(gallery.tileCount(), 6);
    QTRY_VERIFY_WITH_TIMEOUT(allRendered(gallery), 300000);
    const double all = clock.elapsed();
    QCoreApplication::processEvents();
    QVERIFY(editor->grab().save(out + "/tf-gallery.png"));
    QString each;
    for (double t : ms) each += QString(" %1").arg(t, 0, 'f', 0);
    qInfo("cranium 256x256x108: %d pictures of 96x96 in %.0f ms from the tab shown; each (ms):%s",
          gallery.tileCount(), all, qPrintable(each));
  }
};

QTEST_MAIN(TfGalleryTest)
#include "tf_gallery_test.moc"
