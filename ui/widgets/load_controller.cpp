#include "load_controller.h"

#include <algorithm>

#include <QTimer>

#include "gui_post.h"
#include "voxray/io/error.h"
#ifdef VOXRAY_HAS_DICOM  // the PACS client's library, which reads OME-Zarr URLs too
#include "voxray/io/zarr_url.h"
#endif

namespace voxray::ui {

LoadController::LoadController(QWidget* dialogParent)
    : QObject(dialogParent), dialogParent_(dialogParent), task_(postTo(this)) {
  qRegisterMetaType<std::shared_ptr<const Volume>>("std::shared_ptr<const voxray::Volume>");
  qRegisterMetaType<VolumeSeries>("voxray::VolumeSeries");
}

LoadController::~LoadController() = default;  // task_ cancels and waits

void LoadController::load(const std::string& input, LoadOptions options, const QString& name) {
  if (busy_) return;
  busy_ = true;
  name_ = name;
  input_ = QString::fromStdString(input);
  dialog_ = new QProgressDialog("Loading " + name + " …", "Cancel", 0, 1000, dialogParent_);
  dialog_->setWindowModality(Qt::WindowModal);
  dialog_->setMinimumDuration(300);  // quick loads show no dialog at all
  connect(dialog_, &QProgressDialog::canceled, this, &LoadController::cancel);
  task_.start([this, input, options]() mutable {
    options.cancel = task_.cancelFlag();
    options.progress = [this](double p, const std::string&) {
      task_.post([this, p] { showProgress(p); });
    };
    VolumeSeries series;
    QString error;
    bool wasCancelled = false;
    try {
      // Every time point at once (all resident in memory, issue 36): playing then never
      // waits for the disk; a 10-phase 512x512x256 series takes 1.25 GiB.
#ifdef VOXRAY_HAS_DICOM  // an http(s) URL opens as a remote OME-Zarr
      for (Volume& v : loadVolumeSeriesOrUrl(input, options))
#else
      for (Volume& v : loadVolumeSeries(input, options))
#endif
        series.push_back(std::make_shared<const Volume>(std::move(v)));
      if (options.timePoint && *options.timePoint >= int(series.size()))
        throw inputError(input + ": --time " + std::to_string(*options.timePoint) +
                         " is out of range: it has " + std::to_string(series.size()) +
                         " time point(s), 0 ... " + std::to_string(series.size() - 1));
    } catch (const std::exception& e) {
      wasCancelled = isCancellation(e);
      error = QString::fromStdString(e.what());
      series.clear();
    }
    task_.post([this, series = std::move(series), error, wasCancelled]() mutable {
      finish(std::move(series), error, wasCancelled);
    });
  });
}

void LoadController::showProgress(double fraction) {
  // Slices finish out of order on the importer's threads: the bar only moves forward.
  if (!dialog_ || settingValue_) return;
  settingValue_ = true;
  dialog_->setValue(std::max(dialog_->value(), int(fraction * 999)));
  settingValue_ = false;
}

void LoadController::finish(VolumeSeries series, const QString& error, bool wasCancelled) {
  if (settingValue_) {  // called from inside the box's setValue: once it has returned
    QTimer::singleShot(0, this, [this, series = std::move(series), error, wasCancelled]() mutable {
      finish(std::move(series), error, wasCancelled);
    });
    return;
  }
  task_.wait();  // the job has posted its last event: it returns at once
  busy_ = false;
  // Gone now, not when a deleteLater comes: the error box that may follow runs its own
  // event loop, in which a deferred delete does not happen, and there the box's show timer
  // (started by its first progress value; hide() does not stop it) brought it back up over
  // the message, modal. Nothing of the box's is on the stack here: this runs from the
  // task's posted event.
  delete dialog_;
  // A load that finished while the user pressed Cancel is dropped too: they asked for
  // nothing to change.
  if (wasCancelled || task_.cancelled())
    emit cancelled();
  else if (!series.empty())
    emit loaded(std::move(series), name_, input_);
  else
    emit failed(error);
}

}  // namespace voxray::ui
