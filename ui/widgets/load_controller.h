#pragma once
// Loads volumes on a worker thread through voxray::loadVolume, with a progress dialog
// that can cancel. The window stays responsive; the result or the importer's message
// arrives as a signal on the UI thread.
#include <atomic>
#include <memory>
#include <thread>

#include <QObject>
#include <QPointer>
#include <QProgressDialog>
#include <QTimer>

#include "voxray/io/load.h"

namespace voxray::ui {

class LoadController : public QObject {
  Q_OBJECT
 public:
  explicit LoadController(QWidget* dialogParent);
  ~LoadController() override;  // cancels and waits for a load in progress

  bool busy() const { return worker_.joinable(); }
  // INPUT and OPTIONS as loadVolume takes them (progress and cancel are filled in here).
  // NAME: what the window title shows. Ignored while another load runs.
  void load(const std::string& input, LoadOptions options, const QString& name);

 signals:
  void loaded(std::shared_ptr<const voxray::Volume> volume, const QString& name,
              const QString& input);
  void failed(const QString& message, bool cancelled);

 private:
  void poll();

  QWidget* dialogParent_;
  QPointer<QProgressDialog> dialog_;
  QTimer poll_;
  std::thread worker_;
  std::atomic<bool> cancel_{false};
  std::atomic<bool> done_{false};
  std::atomic<double> progress_{0.0};
  std::shared_ptr<const Volume> result_;
  std::string error_;
  QString name_, input_;
};

}  // namespace voxray::ui
