// Issue 38 part 2 through the real widgets (offscreen): a study larger than the GPU memory
// budget is drawn out of core; the 3D view says "Not at full resolution (k of n parts)" over
// a drag's preview frames and nothing once the mouse is released and the frame converges. The
// budget is a preference: its spin box edits the model and it round-trips through the saved
// settings.
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>

#include "settings_store.h"
#include "study_state.h"
#include "voxray/io/orientation.h"
#include "voxray/io/raw_import.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

class OutOfCoreViewTest : public QObject {
  Q_OBJECT

 private slots:
  void budgetSettingRoundTrips() {
    test::PhantomWindow w;
    QVERIFY(w.start());
    auto* budget = w.window->findChild<QSpinBox*>("gpuBudget");
    QVERIFY(budget);
    QCOMPARE(budget->value(), 0);
    QCOMPARE(budget->text(), QString("automatic"));  // 0: the device decides
    budget->setValue(2048);
    QCOMPARE(w.models->render.quality().gpuBudgetMib, 2048);
    QTemporaryDir dir;
    {
      QSettings s(dir.filePath("voxray.ini"), QSettings::IniFormat);
      saveModelSettings(s, *w.models);
    }
    AppModels fresh;
    QCOMPARE(fresh.render.quality().gpuBudgetMib, 0);
    {
      QSettings s(dir.filePath("voxray.ini"), QSettings::IniFormat);
      loadModelSettings(s, fresh);
    }
    QCOMPARE(fresh.render.quality().gpuBudgetMib, 2048);
    // The spin box follows the model (a loaded preference, an undo).
    Quality q = w.models->render.quality();
    q.gpuBudgetMib = 512;
    w.models->render.setQuality(q);
    QCOMPARE(budget->value(), 512);
    w.stop();
  }

  void noteShowsDuringDragAndGoesAfterRelease() {
    test::PhantomWindow w;
    QVERIFY(w.start());
    // A 128^3 study (4 MiB) under a 1 MiB budget: out of core, about 8 parts on the device of
    // about 32 (OutOfCoreOptions::partSlices' default).
    w.window->findChild<QSpinBox*>("gpuBudget")->setValue(1);
    auto big = std::make_shared<const Volume>(makeHeadPhantom(128));
    QVERIFY(big->byteSize() > (size_t(1) << 20));
    w.models->crosshair.setDims(big->dims);
    w.models->document.set(big, "phantom 128");
    VolumeView& view = w.window->volumeView();
    test::settledFrame(*w.window);
    QVERIFY(!view.lastFrame().isNull());
    QCOMPARE(view.frameNote(), QString());  // converged
    // No Raycaster variants to build for it: the status does not wait for them.
    QCOMPARE(w.window->findChild<QLabel*>("preparingLabel")->text(), QString());
    // Each frame as the view shows it, with the note it then says (the view's slot runs
    // first: it connected first).
    struct Seen {
      bool interactive, outOfCore;
      QString note;
    };
    std::vector<Seen> seen;
    connect(&w.window->scheduler(), &RenderScheduler::frameReady, this,
            [&](std::shared_ptr<const Frame> f) {
              seen.push_back({f->interactive, f->outOfCore, view.frameNote()});
            });
    auto send = [&view](QEvent::Type type, QPointF at, Qt::MouseButton b, Qt::MouseButtons held) {
      QMouseEvent e(type, at, view.mapToGlobal(at), b, held, Qt::NoModifier);
      QApplication::sendEvent(&view, &e);
    };
    const QPointF from = view.rect().center();
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= 4; ++i) {
      send(QEvent::MouseMove, from + QPointF(15.0 * i, 4.0 * i), Qt::NoButton, Qt::LeftButton);
      QTest::qWait(20);
    }
    QDeadlineTimer deadline(60000);
    auto dragFrames = [&] {
      return std::count_if(seen.begin(), seen.end(), [](const Seen& s) { return s.interactive; });
    };
    while (dragFrames() == 0 && !deadline.hasExpired()) QTest::qWait(50);
    QVERIFY(dragFrames() > 0);
    send(QEvent::MouseButtonRelease, from + QPointF(60.0, 16.0), Qt::LeftButton, Qt::NoButton);
    test::settledFrame(*w.window);
    // Every drag frame was a preview (the parts not on the device drawn coarse) and said so.
    for (const Seen& s : seen) {
      if (!s.interactive) continue;
      QVERIFY(s.outOfCore);
      QVERIFY2(s.note.startsWith("Not at full resolution ("), qPrintable(s.note));
      QVERIFY2(s.note.contains(" parts)"), qPrintable(s.note));
    }
    qInfo("%d frames, %d of them drag frames; the first drag frame said \"%s\"", int(seen.size()),
          int(dragFrames()), qPrintable(std::find_if(seen.begin(), seen.end(), [](const Seen& s) {
                                          return s.interactive;
                                        })->note));
    // After the release the last frame converged: no note.
    QVERIFY(!seen.empty());
    QVERIFY(!seen.back().interactive);
    QVERIFY(seen.back().outOfCore);
    QCOMPARE(view.frameNote(), QString());
    w.stop();
  }

  // The README's picture (not a check): CThead under an 8 MiB budget, grabbed at a drag's
  // preview frame, the note in the 3D view's top right corner. Written under Xvfb by
  // VOXRAY_OUT_OF_CORE_SHOT=docs/images/out-of-core-drag.png xvfb-run -a -s "-screen 0
  // 1920x1080x24" build/bin/voxray_ui_out_of_core_view_tests readmeScreenshot.
  void readmeScreenshot() {
    const QString shot = qEnvironmentVariable("VOXRAY_OUT_OF_CORE_SHOT");
    if (shot.isEmpty()) QSKIP("set VOXRAY_OUT_OF_CORE_SHOT=PATH to write the README's screenshot");
    test::PhantomWindow w;
    QVERIFY(w.start());
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
    Quality q = w.models->render.quality();
    q.resolution = {0, 0};  // the view's size
    q.gpuBudgetMib = 8;
    w.models->render.setQuality(q);
    w.window->resize(1900, 1040);
    openStudy(*w.models, v, "CThead");
    VolumeView& view = w.window->volumeView();
    test::settledFrame(*w.window);
    bool saved = false;
    connect(&w.window->scheduler(), &RenderScheduler::frameReady, this,
            [&](std::shared_ptr<const Frame> f) {
              if (f->interactive && !saved && !view.frameNote().isEmpty())
                saved = w.window->grab().save(shot);
            });
    auto send = [&view](QEvent::Type type, QPointF at, Qt::MouseButton b, Qt::MouseButtons held) {
      QMouseEvent e(type, at, view.mapToGlobal(at), b, held, Qt::NoModifier);
      QApplication::sendEvent(&view, &e);
    };
    const QPointF from = view.rect().center();
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    QDeadlineTimer deadline(120000);
    for (int i = 1; !saved && !deadline.hasExpired(); ++i) {
      send(QEvent::MouseMove, from + QPointF(6.0 * (i % 40), 0.0), Qt::NoButton, Qt::LeftButton);
      QTest::qWait(30);
    }
    send(QEvent::MouseButtonRelease, from, Qt::LeftButton, Qt::NoButton);
    QVERIFY(saved);
    w.stop();
  }
};

QTEST_MAIN(OutOfCoreViewTest)
#include "out_of_core_view_test.moc"
