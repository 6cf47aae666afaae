// QTest on the offscreen platform, issue 35: the transfer-function editor. A click on the
// curve adds a point at the HU and opacity under the mouse, a drag moves it and renders a new
// 3D frame, Delete removes it, the histogram counts the open volume, and a bad file leaves
// the transfer function as it was with a message naming the field.
#include <QAction>
#include <QFile>
#include <QTemporaryDir>

#include "tf_editor_dialog.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

TfEditorDialog* openEditor(MainWindow& window) {
  auto* action = window.findChild<QAction*>("viewTfEditor");
  if (!action) return nullptr;
  action->trigger();
  return window.findChild<TfEditorDialog*>("tfEditor");
}

}  // namespace

class TfEditorTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void clickAddsDragMovesAndDeleteRemovesAPoint() {
    MainWindow& window = *fixture_.window;
    AppModels& models = *fixture_.models;
    models.render.applyPreset("CT-Bone");
    const QImage bone = test::settledFrame(window);
    TfEditorDialog* editor = openEditor(window);
    QVERIFY(editor);
    QVERIFY(editor->isVisible());
    TfCurveView& curve = editor->curve();
    curve.setHuRange(-1000.0, 2000.0);
    QVERIFY(QTest::qWaitForWindowExposed(editor));
    const size_t before = editor->model().property().opacity.size();

    // A click where the curve is 0 (HU -500 in CT-Bone) adds a point there, at the opacity
    // of the pixel row clicked: 0.5 of the axis (whose top is 1).
    const QPoint at(int(std::lround(curve.xOf(-500.0))), int(std::lround(curve.yOf(0.5))));
    QTest::mousePress(&curve, Qt::LeftButton, {}, at);
    QTest::mouseRelease(&curve, Qt::LeftButton, {}, at);
    const VolumeProperty& vp = editor->model().property();
    QCOMPARE(vp.opacity.size(), before + 1);
    auto sel = curve.selection();
    QVERIFY(sel && sel->list == TfCurveView::List::Opacity);
    const OpacityNode added = vp.opacity[sel->index];
    // One pixel of the axis is (3000 HU / width) and (1 / height) of opacity.
    QVERIFY2(std::abs(added.x + 500.0) <= 3000.0 / curve.curveArea().width(),
             qPrintable(QString::number(added.x)));
    QVERIFY(std::abs(added.opacity - 0.5) <= 1.0 / curve.curveArea().height());
    // What the 3D view renders is the editor's table: the soft tissue at -500 HU is now
    // half opaque, so the frame changes.
    QCOMPARE(models.render.params().transferFunction, renderTable(vp));
    QVERIFY(models.render.params().preset.empty());
    const QImage withPoint = test::settledFrame(window);
    QVERIFY(test::differingPixels(bone, withPoint) > 100);

    // A drag moves the point: to -300 HU at opacity 0.25, in one undo step. (Past CT-Bone's
    // next point, at -16 HU, it would stop there: the list stays sorted.)
    const QPoint to(int(std::lround(curve.xOf(-300.0))), int(std::lround(curve.yOf(0.25))));
    QTest::mousePress(&curve, Qt::LeftButton, {}, at);
    QTest::mouseMove(&curve, (at + to) / 2);
    QTest::mouseMove(&curve, to);
    QTest::mouseRelease(&curve, Qt::LeftButton, {}, to);
    const OpacityNode moved = editor->model().property().opacity[curve.selection()->index];
    QVERIFY2(std::abs(moved.x + 300.0) <= 3000.0 / curve.curveArea().width(),
             qPrintable(QString("%1 %2").arg(moved.x).arg(moved.opacity)));
    QVERIFY(std::abs(moved.opacity - 0.25) <= 1.0 / curve.curveArea().height());
    auto* hu = editor->findChild<QDoubleSpinBox*>("tfPointHu");
    QVERIFY(hu);
    QCOMPARE(hu->value(), std::round(moved.x * 10.0) / 10.0);  // one decimal shown
    editor->model().undo();
    QCOMPARE(editor->model().property().opacity[curve.selection()->index], added);
    editor->model().redo();

    // Delete removes it, and the view is CT-Bone's table again.
    curve.setFocus();
    QTest::keyClick(&curve, Qt::Key_Delete);
    QCOMPARE(editor->model().property().opacity.size(), before);
    QCOMPARE(models.render.params().transferFunction, findPreset("CT-Bone").tf.points);
    QCOMPARE(test::differingPixels(bone, test::settledFrame(window)), 0);
  }

  void histogramCountsTheOpenVolume() {
    MainWindow& window = *fixture_.window;
    TfEditorDialog* editor = openEditor(window);
    QVERIFY(editor);
    QTRY_VERIFY_WITH_TIMEOUT(editor->histogramReady(), 10000);
    auto* status = editor->findChild<QLabel*>("tfStatus");
    QVERIFY(status);
    // The 64^3 phantom: every voxel counted.
    QVERIFY2(status->text().startsWith("Histogram of 262144 voxels"), qPrintable(status->text()));
    // The HU axis starts at the volume's range (the phantom's air is -1000 HU).
    QCOMPARE(editor->curve().huLo(), -1000.0);
  }

  void aBadFileKeepsTheTransferFunctionAndNamesTheField() {
    MainWindow& window = *fixture_.window;
    TfEditorDialog* editor = openEditor(window);
    QVERIFY(editor);
    const VolumeProperty before = editor->model().property();
    const std::vector<ControlPoint> table = fixture_.models->render.params().transferFunction;
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.vp");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("1\n1\n0.9\n0.1\n0.2\n10\n4 0 0 100 1.5\n4 0 1 255 1\n4 0 1 1 1\n");
    f.close();
    const QString error = editor->loadFile(bad);
    QCOMPARE(error, bad + ": opacity point 2 has 1.5; it must lie in 0 ... 1");
    QCOMPARE(editor->model().property(), before);
    QCOMPARE(fixture_.models->render.params().transferFunction, table);
    // A good file saved and read back is the same transfer function.
    editor->model().addOpacityPoint(321.0, 0.123);
    const QString good = dir.filePath("mine.json");
    QCOMPARE(editor->saveFile(good), QString());
    const VolumeProperty saved = editor->model().property();
    editor->model().undo();
    QCOMPARE(editor->loadFile(good), QString());
    QCOMPARE(editor->model().property(), saved);

    // A Slicer preset list: the user picks one of its presets.
    const QString list = dir.filePath("presets.xml");
    QFile x(list);
    QVERIFY(x.open(QIODevice::WriteOnly));
    x.write(R"(<PresetList><VolumeProperty name="A" interpolation="1" shade="1" ambient="0.1"
      diffuse="0.9" specular="0.2" specularPower="10" gradientOpacity="4 0 1 255 1"
      scalarOpacity="4 0 0 100 0.5" colorTransfer="4 0 1 0 0"/><VolumeProperty name="B"
      interpolation="1" shade="1" ambient="0.1" diffuse="0.9" specular="0.2" specularPower="10"
      gradientOpacity="4 0 1 255 1" scalarOpacity="4 -200 0 300 0.25"
      colorTransfer="4 0 0 0 1"/></PresetList>)");
    x.close();
    QStringList offered;
    editor->choosePreset = [&](const QStringList& names) {
      offered = names;
      return QString("B");
    };
    QCOMPARE(editor->loadFile(list), QString());
    QCOMPARE(offered, (QStringList{"A", "B"}));
    QCOMPARE(editor->model().property().name, std::string("B"));
    QCOMPARE(editor->model().property().opacity[1], (OpacityNode{300.0, 0.25}));
  }
};

QTEST_MAIN(TfEditorTest)
#include "tf_editor_test.moc"
