#pragma once
// Runs a movie export (MovieExportTask) behind a progress dialog that shows the frame, an
// estimate of the time left and a Cancel button; the window stays usable meanwhile. The
// outcome arrives on the GUI thread: written, cancelled (no error, nothing written) or the
// writer's or renderer's message.
#include <functional>
#include <memory>

#include <QObject>
#include <QPointer>
#include <QProgressDialog>

#include "movie_export.h"

namespace voxray::ui {

class MovieController : public QObject {
  Q_OBJECT
 public:
  // Destroyed, it cancels and waits for an export in progress (task_'s BackgroundTask).
  explicit MovieController(QWidget* dialogParent);
  void start(std::shared_ptr<const Volume> volume, const std::string& device, MoviePlan plan,
             const QString& path, MovieSettings settings);
  // Renders an orbit's frame of a volume on the device that holds it (the 3D view's:
  // RenderScheduler::renderOnDevice), so that an export uploads no second copy; unset: the
  // export makes a context of its own.
  using OnDevice = std::function<Image(const RenderParams&, const Volume*)>;
  void setOnDevice(OnDevice render) { onDevice_ = std::move(render); }
  void cancel() { task_.cancel(); }
  bool busy() const { return task_.busy(); }

 signals:
  void written(const QString& path);
  void failed(const QString& message);
  void cancelled();

 private:
  QWidget* dialogParent_;
  QPointer<QProgressDialog> dialog_;
  OnDevice onDevice_;
  MovieExportTask task_;  // last member: stops before the rest goes
};

}  // namespace voxray::ui
