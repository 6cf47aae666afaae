#pragma once
// Shared by the QTest files: a MainWindow showing a 64^3 head phantom rendered at 128x96
// through PoCL, and waiting for its frames.
#include <memory>

#include <QDeadlineTimer>
#include <QSignalSpy>
#include <QtTest>

#include "main_window.h"
#include "volume_view.h"
#include "voxray/io/phantom.h"

namespace voxray::ui::test {

// Waits until the 3D view shows a full-quality frame rendered after this call.
inline QImage waitFullFrame(MainWindow& window) {
  QSignalSpy spy(&window.scheduler(), &RenderScheduler::frameReady);
  for (int tries = 0; tries < 600; ++tries) {
    if (!spy.isEmpty()) {
      auto f = spy.takeLast().at(0).value<std::shared_ptr<const Frame>>();
      if (!f->interactive) {
        QCoreApplication::processEvents();
        return window.volumeView().lastFrame();
      }
    }
    spy.wait(100);
  }
  qFatal("no full-quality frame within 60 s");
}

// The frame on screen once frames stop arriving (none for 1.5 s) and SCHEDULER has nothing
// waiting: requests made while a frame renders are answered after it, so the first frame after
// a change may show an earlier state; and a kernel variant still building (seconds on a cold
// PoCL cache, as on a fresh CI machine) is quiet too. Waits up to 60 s.
inline QImage settledFrame(RenderScheduler& scheduler, const VolumeView& view) {
  QSignalSpy frames(&scheduler, &RenderScheduler::frameReady);
  QDeadlineTimer deadline(60000);
  do {
    while (frames.wait(1500)) {
    }
  } while (scheduler.busy() && !deadline.hasExpired());
  QCoreApplication::processEvents();
  return view.lastFrame();
}

inline QImage settledFrame(MainWindow& window) {
  return settledFrame(window.scheduler(), window.volumeView());
}

// The settled frame after a change that alters the image: first waits (up to 60 s) for a frame
// other than BEFORE, since a new kernel variant (e.g. the 2D table's) is compiled before its
// first frame, which on a loaded 2-core machine takes longer than settledFrame's quiet interval.
inline QImage changedFrame(MainWindow& window, const QImage& before) {
  QSignalSpy frames(&window.scheduler(), &RenderScheduler::frameReady);
  QDeadlineTimer deadline(60000);
  while (window.volumeView().lastFrame() == before && !deadline.hasExpired()) {
    frames.wait(1000);
    QCoreApplication::processEvents();
  }
  return settledFrame(window);
}

// The models and a shown window with the phantom's first full frame on screen.
struct PhantomWindow {
  std::unique_ptr<AppModels> models = std::make_unique<AppModels>();
  std::unique_ptr<MainWindow> window;

  bool start() {
    // Fresh models for each test function when the whole class runs in one process (ctest
    // runs each function alone; stop() drops the last test's).
    if (!models) models = std::make_unique<AppModels>();
    window = std::make_unique<MainWindow>(*models, "cpu");
    Quality q;
    q.resolution = {128, 96};
    models->render.setQuality(q);
    window->resize(900, 700);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) return false;
    auto v = std::make_shared<const Volume>(makeHeadPhantom(64));
    models->crosshair.setDims(v->dims);
    models->document.set(v, "phantom");
    waitFullFrame(*window);
    return true;
  }
  void stop() {
    window.reset();  // widgets go before the models they are bound to
    models.reset();
  }
};

inline int differingPixels(const QImage& a, const QImage& b) {
  if (a.size() != b.size()) return a.width() * a.height();
  int n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) n += a.pixel(x, y) != b.pixel(x, y);
  return n;
}

}  // namespace voxray::ui::test
