// voxray: the Qt workstation. Opens INPUT (or the head phantom) with voxray-cli's raw
// flags and render parameters; --screenshot/--quit-after-first-frame serve the smoke test.
#include <QApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QMessageBox>
#include <QTimer>

#include <iostream>
#include <memory>

#include "compare_view.h"
#include "main_window.h"
#include "qt_image.h"
#include "session_state.h"
#include "slice_view.h"
#include "start_options.h"
#include "study_browser_model.h"
#include "volume_view.h"
#include "voxray/io/error.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

void nameApplication() {
  QCoreApplication::setOrganizationName("Voxray");
  QCoreApplication::setApplicationName("voxray");
  QCoreApplication::setApplicationVersion("0.1.0");
}

// --startup-times: when the axial view and the 3D view first painted an image, and when the
// first sharp 3D frame arrived, in ms since main began (issue 41 item 9 measures these).
class StartupClock : public QObject {
 public:
  StartupClock(MainWindow& w, const QElapsedTimer& since) : window_(w), since_(since) {
    w.sliceView(0).installEventFilter(this);
    w.volumeView().installEventFilter(this);
    QObject::connect(&w.scheduler(), &RenderScheduler::firstFullFrame, this, [this] {
      if (sharpMs_ < 0) sharpMs_ = since_.elapsed();
      std::cerr << "voxray: startup: slices " << slicesMs_ << " ms, first 3D image " << imageMs_
                << " ms, sharp 3D frame " << sharpMs_ << " ms\n";
    });
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override {
    if (e->type() == QEvent::Paint) {
      if (slicesMs_ < 0 && watched == &window_.sliceView(0) &&
          !window_.sliceView(0).sliceImage().isNull())
        slicesMs_ = since_.elapsed();
      if (imageMs_ < 0 && watched == &window_.volumeView() &&
          !window_.volumeView().lastFrame().isNull())
        imageMs_ = since_.elapsed();
    }
    return false;
  }

 private:
  MainWindow& window_;
  const QElapsedTimer& since_;
  qint64 slicesMs_ = -1, imageMs_ = -1, sharpMs_ = -1;
};

}  // namespace

int main(int argc, char** argv) {
  QElapsedTimer sinceStart;
  sinceStart.start();
  // --help and --version print and exit: a QCoreApplication answers them, so that they work
  // without a display (a QApplication aborts without one). An option that took "--help" as
  // its value leaves the parser without exiting: then the workstation starts as usual.
  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  if (asksForHelpOrVersion(arguments)) {
    QCoreApplication core(argc, argv);
    nameApplication();
    try {
      parseStartOptions(QCoreApplication::arguments());
    } catch (const std::exception& e) {
      std::cerr << "voxray: " << e.what() << "\n";
      return 2;
    }
  }
  QApplication app(argc, argv);
  nameApplication();
  QApplication::setWindowIcon(QIcon::fromTheme("voxray"));

  StartOptions options;
  try {
    options = parseStartOptions(QApplication::arguments());
  } catch (const std::exception& e) {  // voxray::Error, or a bug: a message, never an abort
    std::cerr << "voxray: " << e.what() << "\n";
    return 2;
  }
  auto models = std::make_unique<AppModels>();
  auto window = std::make_unique<MainWindow>(*models, QString::fromStdString(options.device));
  if (!options.resetSettings && options.screenshot.empty()) window->restoreSettings();
  try {
    models->render.applyValues(options.renderValues);
  } catch (const std::exception& e) {
    std::cerr << "voxray: " << e.what() << "\n";
    return 2;
  }

  std::unique_ptr<StartupClock> clock;
  if (options.startupTimes) clock = std::make_unique<StartupClock>(*window, sinceStart);
  int exitCode = 0;
  // --overlay and --compare: loaded once the study is shown (their loaders need it).
  if (!options.overlay.empty() || !options.prior.empty()) {
    auto* once = new QObject(window.get());
    QObject::connect(window.get(), &MainWindow::volumeShown, once, [&, once] {
      if (!options.overlay.empty()) window->openOverlay(options.overlay);
      if (!options.prior.empty()) window->openPrior(options.prior);
      once->deleteLater();
    });
  }
  // The screenshot waits for them too (polled: the overlay's and prior's loads end on their
  // own threads), then for the fused 3D frame.
  auto extrasShown = [&] {
    return (options.overlay.empty() || models->fusion.overlay()) &&
           (options.prior.empty() || (window->compareView() && window->compareView()->hasPrior() &&
                                      !window->compareView()->moving3dView().lastFrame().isNull()));
  };
  if (!options.screenshot.empty() || options.quitAfterFirstFrame) {
    QObject::connect(&window->scheduler(), &RenderScheduler::firstFullFrame, window.get(), [&] {
      // Let the view paint the frame (and the extras load and render) before grabbing.
      auto* wait = new QTimer(window.get());
      QObject::connect(wait, &QTimer::timeout, window.get(), [&, wait] {
        if (!extrasShown()) return;
        wait->deleteLater();
        const bool extras = !options.overlay.empty() || !options.prior.empty();
        QTimer::singleShot(extras ? 3000 : 200, window.get(), [&] {
          if (!options.screenshot.empty()) {
            try {
              writeImage(options.screenshot, fromQImage(window->grab().toImage()));
            } catch (const std::exception& e) {
              std::cerr << "voxray: " << e.what() << "\n";
              exitCode = 1;
            }
          }
          if (options.quitAfterFirstFrame) QApplication::exit(exitCode);
        });
      });
      wait->start(100);
    });
    QObject::connect(&window->loader(), &LoadController::failed, window.get(),
                     [&](const QString& message) {
                       std::cerr << "voxray: " << message.toStdString() << "\n";
                       if (options.quitAfterFirstFrame) QApplication::exit(1);
                     });
    // A cancelled first load leaves nothing to capture: end as a failed one did.
    QObject::connect(&window->loader(), &LoadController::cancelled, window.get(), [&] {
      std::cerr << "voxray: loading cancelled\n";
      if (options.quitAfterFirstFrame) QApplication::exit(1);
    });
    QObject::connect(&window->scheduler(), &RenderScheduler::renderError, window.get(),
                     [&](const QString& message) {
                       std::cerr << "voxray: " << message.toStdString() << "\n";
                       if (options.quitAfterFirstFrame) QApplication::exit(1);
                     });
  }
  window->show();
  // The camera, clip and light values given belong to the volume opened here: it starts
  // from its own defaults, then takes them (the preferences among them are applied above).
  if (isSessionPath(options.input))
    window->sessions().openFile(options.input);  // a session file: its own state
  else
    window->open(options.input, options.load, options.renderValues);
#ifdef VOXRAY_HAS_STUDYDB
  // Without a file and with studies in the database: the list of studies first.
  if (opensStudyBrowserAtStart(options, StudyBrowserModel::hasStudies()))
    window->showStudyBrowser();
#endif
  int rc = app.exec();
  clock.reset();
  window.reset();  // widgets go before the models they are bound to
  return rc != 0 ? rc : exitCode;
}
