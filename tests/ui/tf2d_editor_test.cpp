// QTest on the offscreen platform, issue 35: the 2D transfer-function tab of the editor. The
// value x |gradient| histogram counts the open volume, the right-click menu adds a rectangle
// under the mouse, a drag moves it by the HU and HU/mm its pixels are worth, the 3D view
// renders what the editor holds (RenderParams::tf2d), and a saved JSON keeps it.
#include <QAction>
#include <QPainter>
#include <QTemporaryDir>

#include "tf_editor_dialog.h"
#include "voxray/io/raw_import.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

TfEditorDialog* openEditorOn2d(MainWindow& window) {
  auto* action = window.findChild<QAction*>("viewTfEditor");
  if (!action) return nullptr;
  action->trigger();
  auto* editor = window.findChild<TfEditorDialog*>("tfEditor");
  if (editor) editor->tabs().setCurrentIndex(1);
  return editor;
}

}  // namespace

class Tf2dEditorTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void histogram2dCountsTheOpenVolume() {
    TfEditorDialog* editor = openEditorOn2d(*fixture_.window);
    QVERIFY(editor);
    QTRY_VERIFY_WITH_TIMEOUT(editor->tf2dHistogramReady(), 20000);
    auto* status = editor->findChild<QLabel*>("tf2dStatus");
    QVERIFY(status);
    // The 64^3 phantom: every voxel counted; its HU axis starts at the phantom's air.
    QVERIFY2(status->text().startsWith("2D histogram of 262144 voxels"),
             qPrintable(status->text()));
    QCOMPARE(editor->tf2d().huLo(), -1000.0);
    QVERIFY(editor->tf2d().gradientTop() >= 8.0);  // rounded up to a multiple of 8 HU/mm
    // Another volume while the tab shows: counted again (a 32^3 phantom: 32768 voxels).
    auto small = std::make_shared<const Volume>(makeHeadPhantom(32));
    fixture_.models->crosshair.setDims(small->dims);
    fixture_.models->document.set(small, "small");
    QTRY_VERIFY_WITH_TIMEOUT(editor->tf2dHistogramReady(), 20000);
    QVERIFY2(status->text().startsWith("2D histogram of 32768 voxels"), qPrintable(status->text()));
  }

  void menuAddsARectangleAndADragMovesItsHuRange() {
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    models.render.applyPreset("CT-Bone");
    const QImage bone = test::settledFrame(window);
    TfEditorDialog* editor = openEditorOn2d(window);
    QVERIFY(editor);
    QTRY_VERIFY_WITH_TIMEOUT(editor->tf2dHistogramReady(), 20000);
    Tf2dView& view = editor->tf2d();
    QVERIFY(QTest::qWaitForWindowExposed(editor));
    const QRectF area = view.plotArea();
    const QPoint at = area.center().toPoint();

    // The menu's "Add rectangle" at the centre: a rectangle centred on the HU and |gradient|
    // under the mouse, an eighth of the HU axis wide.
    std::unique_ptr<QMenu> menu(view.menuAt(at));
    auto* add = menu->findChild<QAction*>("tf2dAddRect");
    QVERIFY(add);
    add->trigger();
    const Tf2d& tf = editor->model().property().tf2d;
    QCOMPARE(tf.primitives.size(), size_t(1));
    const Tf2dPrimitive added = tf.primitives[0];
    QCOMPARE(added.shape, Tf2dShape::Rectangle);
    const double huPerPixel = (view.huHi() - view.huLo()) / area.width();
    const double gPerPixel = view.gradientTop() / area.height();
    QVERIFY(std::abs(0.5 * (added.hu0 + added.hu1) - view.huAt(at.x())) < 1e-9);
    QVERIFY(std::abs((added.hu1 - added.hu0) - (view.huHi() - view.huLo()) / 8.0) < 1e-9);
    QCOMPARE(tf.gradientMax, view.gradientTop());  // the table's top row is the axis' top
    QCOMPARE(view.selection(), std::optional<size_t>(0));

    // What the 3D view renders carries it, and the frame is the 2D function's, not CT-Bone's.
    QCOMPARE(models.render.params().tf2d, tf);
    QCOMPARE(window.scheduler().fullParams().tf2d, tf);
    const QImage with2d = test::changedFrame(window, bone);
    QVERIFY(test::differingPixels(bone, with2d) > 100);

    // A drag of the body by (+40, -20) pixels moves the HU range by 40 pixels' worth of HU
    // and the gradient range up by 20 pixels' worth of HU/mm, in one undo step. The mapping
    // is linear, so the only error is floating point (1e-9 of ~4000 HU).
    const QPoint from = at + QPoint(3, 3);  // inside, off the centre
    const QPoint to = from + QPoint(40, -20);
    QTest::mousePress(&view, Qt::LeftButton, {}, from);
    QTest::mouseMove(&view, from + QPoint(20, -10));
    QTest::mouseMove(&view, to);
    QTest::mouseRelease(&view, Qt::LeftButton, {}, to);
    const Tf2dPrimitive moved = editor->model().property().tf2d.primitives[0];
    QVERIFY2(std::abs(moved.hu0 - (added.hu0 + 40.0 * huPerPixel)) < 1e-9,
             qPrintable(QString("%1 %2 %3").arg(moved.hu0).arg(added.hu0).arg(huPerPixel)));
    QVERIFY(std::abs(moved.hu1 - (added.hu1 + 40.0 * huPerPixel)) < 1e-9);
    QVERIFY(std::abs(moved.g0 - (added.g0 + 20.0 * gPerPixel)) < 1e-9);
    QVERIFY(std::abs(moved.g1 - (added.g1 + 20.0 * gPerPixel)) < 1e-9);
    QCOMPARE(window.scheduler().fullParams().tf2d.primitives[0], moved);
    auto* hu0 = editor->findChild<QDoubleSpinBox*>("tf2dHu0");
    QVERIFY(hu0);
    QCOMPARE(hu0->value(), std::round(moved.hu0 * 10.0) / 10.0);  // one decimal shown

    // Dragging the top-right handle resizes: that corner goes where the mouse is released.
    const QPoint corner(int(std::lround(view.xOf(moved.hu1))),
                        int(std::lround(view.yOf(moved.g1))));
    const QPoint cornerTo = corner + QPoint(30, -10);
    QTest::mousePress(&view, Qt::LeftButton, {}, corner);
    QTest::mouseMove(&view, cornerTo);
    QTest::mouseRelease(&view, Qt::LeftButton, {}, cornerTo);
    const Tf2dPrimitive resized = editor->model().property().tf2d.primitives[0];
    QVERIFY(std::abs(resized.hu1 - view.huAt(cornerTo.x())) < 1e-9);
    QVERIFY(std::abs(resized.g1 - view.gAt(cornerTo.y())) < 1e-9);
    QCOMPARE(resized.hu0, moved.hu0);
    QCOMPARE(resized.g0, moved.g0);

    // Undo twice: the drag was one step.
    editor->model().undo();
    editor->model().undo();
    QCOMPARE(editor->model().property().tf2d.primitives[0], added);

    // Numeric fields edit the selected one.
    auto* opacity = editor->findChild<QDoubleSpinBox*>("tf2dOpacity");
    QVERIFY(opacity);
    opacity->setValue(0.75);
    QCOMPARE(models.render.params().tf2d.primitives[0].opacity, 0.75);

    // Saved as JSON, the tf2d section comes back.
    QTemporaryDir dir;
    const QString file = dir.filePath("tf2d.json");
    QCOMPARE(editor->saveFile(file), QString());
    const VolumeProperty saved = editor->model().property();
    QCOMPARE(readVolumePropertyFile(file.toStdString()).tf2d, saved.tf2d);

    // The menu's Delete on the shape removes it: CT-Bone's frame again.
    std::unique_ptr<QMenu> again(view.menuAt(at));
    auto* del = again->findChild<QAction*>("tf2dDelete");
    QVERIFY(del && del->isEnabled());
    del->trigger();
    QVERIFY(models.render.params().tf2d.empty());
    QCOMPARE(test::differingPixels(bone, test::settledFrame(window)), 0);

    // A triangle from the menu: its apex at |gradient| 0 under the mouse's HU; Delete on the
    // selected one removes it.
    std::unique_ptr<QMenu> third(view.menuAt(at));
    third->findChild<QAction*>("tf2dAddTriangle")->trigger();
    const Tf2dPrimitive tri = editor->model().property().tf2d.primitives.at(0);
    QCOMPARE(tri.shape, Tf2dShape::Triangle);
    QCOMPARE(tri.g0, 0.0);
    QVERIFY(std::abs(0.5 * (tri.hu0 + tri.hu1) - view.huAt(at.x())) < 1e-9);
    view.setFocus();
    QTest::keyClick(&view, Qt::Key_Delete);
    QVERIFY(editor->model().property().tf2d.empty());
  }

  // The README's figure, not a check (not registered with ctest): with VOXRAY_FIGURE_DIR set,
  // the editor's 2D tab on the cranium CT (shared/data/raw/cranium-ct, in HU) with a triangle
  // on the bone boundary and one on the skin, beside the 3D frame it gives.
  void figure2dEditorOnCranium() {
    const QString out = qEnvironmentVariable("VOXRAY_FIGURE_DIR");
    if (out.isEmpty()) QSKIP("set VOXRAY_FIGURE_DIR to write the figure");
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    RawLayout layout;
    layout.dims = {256, 256, 108};
    layout.spacingMm = {0.957, 0.957, 1.5};
    auto v = std::make_shared<const Volume>(importRaw(
        std::string(VOXRAY_DATA_DIR) + "/raw/cranium-ct/cranium_256x256x108_s16le.raw", layout));
    Quality q;
    q.resolution = {480, 480};
    models.render.setQuality(q);
    models.crosshair.setDims(v->dims);
    models.document.set(v, "cranium");
    models.render.applyPreset("CT-Bone");
    TfEditorDialog* editor = openEditorOn2d(window);
    QVERIFY(editor);
    editor->resize(760, 520);
    QTRY_VERIFY_WITH_TIMEOUT(editor->tf2dHistogramReady(), 60000);
    Tf2dView& view = editor->tf2d();
    const double top = view.gradientTop();
    std::unique_ptr<QMenu> menu(view.menuAt(view.plotArea().center()));
    menu->findChild<QAction*>("tf2dAddTriangle")->trigger();
    editor->model().setTf2dExtent(0, 200.0, 2400.0, 0.35 * top, top);
    editor->model().setTf2dColor(0, {0.95, 0.9, 0.8});
    editor->model().setTf2dOpacity(0, 0.7);
    std::unique_ptr<QMenu> skin(view.menuAt(view.plotArea().center()));
    skin->findChild<QAction*>("tf2dAddTriangle")->trigger();
    editor->model().setTf2dExtent(1, -950.0, 50.0, 0.3 * top, top);
    editor->model().setTf2dColor(1, {0.85, 0.55, 0.45});
    editor->model().setTf2dOpacity(1, 0.08);
    const QImage frame = test::settledFrame(window);
    QCoreApplication::processEvents();
    const QImage panel = editor->grab().toImage();
    const QImage shown = frame.scaledToHeight(panel.height(), Qt::SmoothTransformation);
    QImage both(panel.width() + shown.width(), panel.height(), QImage::Format_RGB32);
    both.fill(Qt::black);
    QPainter p(&both);
    p.drawImage(0, 0, panel);
    p.drawImage(panel.width(), 0, shown);
    p.end();
    QVERIFY(both.save(out + "/tf2d-editor.png"));
    qInfo("%s", qPrintable(editor->findChild<QLabel*>("tf2dStatus")->text()));
  }
};

QTEST_MAIN(Tf2dEditorTest)
#include "tf2d_editor_test.moc"
