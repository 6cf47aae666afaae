// voxray: the Qt workstation. Opens INPUT (or the head phantom) with voxray-cli's raw
// flags and render parameters; --screenshot/--quit-after-first-frame serve the smoke test.
#include <QApplication>
#include <QMessageBox>
#include <QTimer>

#include <iostream>
#include <memory>

#include "main_window.h"
#include "qt_image.h"
#include "session_state.h"
#include "start_options.h"
#include "voxray/io/error.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

void nameApplication() {
  QCoreApplication::setOrganizationName("Voxray");
  QCoreApplication::setApplicationName("voxray");
  QCoreApplication::setApplicationVersion("0.1.0");
}

}  // namespace

int main(int argc, char** argv) {
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

  int exitCode = 0;
  if (!options.screenshot.empty() || options.quitAfterFirstFrame) {
    QObject::connect(&window->scheduler(), &RenderScheduler::firstFullFrame, window.get(), [&] {
      // Let the view paint the frame before grabbing the whole window.
      QTimer::singleShot(200, window.get(), [&] {
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
  int rc = app.exec();
  window.reset();  // widgets go before the models they are bound to
  return rc != 0 ? rc : exitCode;
}
