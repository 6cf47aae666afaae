#include "movie_controller.h"

#include "gui_post.h"

namespace voxray::ui {

MovieController::MovieController(QWidget* dialogParent)
    : QObject(dialogParent), dialogParent_(dialogParent), task_(postTo(this)) {}

void MovieController::start(std::shared_ptr<const Volume> volume, const std::string& device,
                            MoviePlan plan, const QString& path, MovieSettings settings) {
  if (busy()) return;
  dialog_ = new QProgressDialog("Exporting the movie …", "Cancel", 0, 1000, dialogParent_);
  dialog_->setObjectName("movieProgress");
  dialog_->setWindowModality(Qt::NonModal);  // the views stay usable while it renders
  dialog_->setMinimumDuration(0);
  dialog_->setAutoClose(false);
  dialog_->setAutoReset(false);
  connect(dialog_, &QProgressDialog::canceled, this, &MovieController::cancel);
  MovieExportTask::Events events;
  events.progress = [this](const MovieProgress& p) {
    if (!dialog_) return;
    dialog_->setValue(p.total > 0 ? p.done * 1000 / p.total : 0);
    dialog_->setLabelText(QString::fromStdString("Exporting the movie: " + describeProgress(p)));
  };
  events.finished = [this, path](const std::string& error, bool wasCancelled) {
    task_.wait();  // the job has posted its last event: it returns at once
    if (dialog_) {
      dialog_->hide();  // before a message box's own event loop (see LoadController)
      dialog_->deleteLater();
    }
    if (wasCancelled)
      emit cancelled();
    else if (!error.empty())
      emit failed(QString::fromStdString(error));
    else
      emit written(path);
  };
  MovieRenderer onDevice;
  if (onDevice_)
    onDevice = [f = onDevice_, v = volume.get()](const RenderParams& p) { return f(p, v); };
  task_.start(std::move(volume), device, std::move(plan), path.toStdString(), settings,
              std::move(events), std::move(onDevice));
}

}  // namespace voxray::ui
