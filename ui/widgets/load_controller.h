#pragma once
// Loads volumes through voxray::loadVolumeSeries as a BackgroundTask (every time point of a
// 4D input, one volume otherwise), with a progress dialog that
// can cancel. The window stays responsive; progress and the outcome arrive on the UI thread:
// the volume, the importer's message, or a cancellation (which is no error).
#include <memory>

#include <QObject>
#include <QPointer>
#include <QProgressDialog>

#include "background_task.h"
#include "time_series.h"
#include "voxray/io/load.h"

namespace voxray::ui {

class LoadController : public QObject {
  Q_OBJECT
 public:
  explicit LoadController(QWidget* dialogParent);
  ~LoadController() override;  // cancels and waits for a load in progress

  bool busy() const { return busy_; }
  // INPUT and OPTIONS as loadVolume takes them (progress and cancel are filled in here).
  // NAME: what the window title shows. Ignored while another load runs.
  void load(const std::string& input, LoadOptions options, const QString& name);
  // As the dialog's Cancel button: the load ends with cancelled(), even if it was finishing.
  void cancel() { task_.cancel(); }

 signals:
  // SERIES: the time points in order (one for a 3D input); OPTIONS.timePoint, when given,
  // is the one to show first.
  void loaded(voxray::VolumeSeries series, const QString& name, const QString& input);
  void failed(const QString& message);
  void cancelled();

 private:
  void showProgress(double fraction);
  void finish(VolumeSeries series, const QString& error, bool wasCancelled);

  QWidget* dialogParent_;
  QPointer<QProgressDialog> dialog_;
  bool busy_ = false;
  // A window-modal progress box's setValue runs the event loop: the load's end may arrive
  // inside it, and must not delete the box under it.
  bool settingValue_ = false;
  QString name_, input_;
  BackgroundTask task_;  // last member: stops before the rest goes
};

}  // namespace voxray::ui
