// Issue 41 items 6 and 9: what a first start shows. The slice views need no OpenCL and show
// the volume at once; the 3D view and the status bar say the renderer is being prepared
// until its first frame, then which kernels still build in the background; the window opens
// large enough for the side panel at 1920x1080; a scale bar's label is never clipped.
#include <QFontMetricsF>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>

#include "slice_overlay.h"
#include "slice_view.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

class FirstStartTest : public QObject {
  Q_OBJECT

  std::unique_ptr<AppModels> models_;
  std::unique_ptr<MainWindow> window_;
  QStringList errors_;

  void open(const QString& device) {
    models_ = std::make_unique<AppModels>();
    window_ = std::make_unique<MainWindow>(*models_, device);
    window_->setErrorSink([this](const QString&, const QString& m) { errors_ << m; });
    Quality q;
    q.resolution = {128, 96};
    models_->render.setQuality(q);
    window_->resize(900, 700);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    auto v = std::make_shared<const Volume>(makeHeadPhantom(64));
    models_->crosshair.setDims(v->dims);
    models_->document.set(v, "phantom");
  }
  QString preparing() const {
    auto* label = window_->statusBar()->findChild<QLabel*>("preparingLabel");
    return label ? label->text() : "(no label)";
  }

 private slots:
  void cleanup() {
    window_.reset();
    models_.reset();
    errors_.clear();
  }

  // The slice views show the volume as soon as it is the document, before any 3D frame
  // (none can have arrived: the render thread's frames come through this event loop),
  // while the 3D view and the status bar say what it waits for.
  void slicesShowAtOnceWhileThe3DViewSaysItIsPreparing() {
    open("cpu");
    for (int i = 0; i < 3; ++i) {
      const QImage& s = window_->sliceView(i).sliceImage();
      QVERIFY2(!s.isNull(), qPrintable(QString("slice view %1 has no image").arg(i)));
      // The phantom's skull is in every plane through the centre: not a black image.
      int bright = 0;
      for (int y = 0; y < s.height(); ++y)
        for (int x = 0; x < s.width(); ++x) bright += qGray(s.pixel(x, y)) > 128;
      QVERIFY2(bright > 20, qPrintable(QString("slice view %1: %2 bright").arg(i).arg(bright)));
    }
    QVERIFY(window_->volumeView().lastFrame().isNull());
    QCOMPARE(window_->volumeView().note(), QString("Preparing the 3D renderer…"));
    QCOMPARE(preparing(), kPreparingRenderer);

    QSignalSpy prepared(&window_->scheduler(), &RenderScheduler::preparingChanged);
    test::waitFullFrame(*window_);
    QCOMPARE(window_->volumeView().note(), QString());
    // Then a drag's kernels and the other modes' build in the background, said so.
    QVERIFY(prepared.wait(5000) || !prepared.isEmpty());
    QCOMPARE(prepared.first().at(0).toInt(), 5);  // one drag + two modes x (still, drag)
    QVERIFY2(preparing().startsWith("Preparing the other 3D modes ("), qPrintable(preparing()));
    for (int tries = 0; tries < 1200 && prepared.last().at(0).toInt() != 0; ++tries)
      prepared.wait(100);
    QCOMPARE(prepared.last().at(0).toInt(), 0);
    QCOMPARE(preparing(), QString());
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));
  }

  // Without any OpenCL device the slices still show; the 3D view says it failed.
  void slicesNeedNoOpenClDevice() {
    open("99");  // no such device: the render thread cannot start
    for (int tries = 0; tries < 100 && errors_.isEmpty(); ++tries) QTest::qWait(50);
    QVERIFY(!errors_.isEmpty());
    for (int i = 0; i < 3; ++i) QVERIFY(!window_->sliceView(i).sliceImage().isNull());
    QVERIFY(window_->volumeView().lastFrame().isNull());
    QCOMPARE(window_->volumeView().note(),
             QString("No 3D image: the renderer failed (see the message)"));
    QCOMPARE(preparing(), QString());
  }

  // 1400x900 scrolled the panel at 1920x1080 and clipped the scale bars' labels.
  void defaultWindowFitsA1080ScreenWithThePanelUnscrolled() {
    QCOMPARE(defaultWindowSize(QSize(1920, 1080)), QSize(1880, 1000));
    QCOMPARE(defaultWindowSize(QSize(1400, 900)), QSize(1380, 860));
    QCOMPARE(defaultWindowSize(QSize()), QSize(1880, 1000));
    open("cpu");
    window_->resize(defaultWindowSize(QSize(1920, 1080)));
    QApplication::processEvents();
    auto* panel = window_->findChild<QScrollArea*>("controlPanel");
    QVERIFY(panel);
    QCOMPARE(panel->verticalScrollBar()->maximum(), 0);
  }

  // The label was as wide as the bar: "50 mm" under a 30-pixel bar showed as "0 mr".
  void scaleBarLabelHoldsItsWholeText() {
    QFont font;
    const QFontMetricsF fm(font);
    const QRect view(0, 0, 200, 300);
    for (double mmPerPixel : {0.9, 2.0, 5.0, 0.1}) {
      const ScaleBar b = scaleBarLayout(fm, mmPerPixel, view);
      const QString what = QString("%1 mm/px: '%2'").arg(mmPerPixel).arg(b.text);
      QVERIFY2(b.label.width() >= fm.horizontalAdvance(b.text), qPrintable(what));
      QVERIFY2(QRectF(view).contains(b.label), qPrintable(what));
      QVERIFY2(b.text.endsWith(" mm"), qPrintable(what));
      // Centred under the bar where there is room.
      QVERIFY2(b.label.center().x() <= b.bar.center().x() + 0.5, qPrintable(what));
    }
    const ScaleBar b = scaleBarLayout(fm, 0.9, view);
    QCOMPARE(b.text, QString("20 mm"));  // a fifth of 200 px at 0.9 mm: 36 mm, rounded down
    QVERIFY(b.bar.length() < fm.horizontalAdvance(b.text));  // the case that was clipped
  }
};

QTEST_MAIN(FirstStartTest)
#include "first_start_test.moc"
