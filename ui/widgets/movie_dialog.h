#pragma once
// File > Export movie: an orbit of the 3D view or a cine through one slice view, its frames,
// size, quality preset (reference by default: the export's quality whatever the view is
// doing) and frame rate, written as MP4 or PNG frames. Existing files are replaced only
// after a yes. Export hands the plan to the MovieController, which renders in the
// background with progress, an estimate and Cancel.
#include <functional>

#include <QDialog>

#include "app_models.h"
#include "movie_controller.h"

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace voxray::ui {

class MovieDialog : public QDialog {
  Q_OBJECT
 public:
  MovieDialog(QWidget* window, AppModels& models, MovieController& controller, QString device);

  // Tests replace the message boxes. CONFIRM is asked with the first existing file and how
  // many of the movie's files exist.
  using ConfirmReplace = std::function<bool(const std::string& first, int count)>;
  void setConfirmReplace(ConfirmReplace confirm) { confirm_ = std::move(confirm); }
  void setErrorSink(std::function<void(const QString&)> sink) { error_ = std::move(sink); }
  // Starts the export of the current choices to PATH. False when nothing starts: the user
  // kept existing files, or the path or the choices are refused (the error sink says why).
  bool exportTo(const QString& path);

 private:
  MovieChoice choice() const;
  void kindChanged();
  void browse(bool folder);
  bool fail(const QString& message);

  AppModels& models_;
  MovieController& controller_;
  QString device_;
  QComboBox* kind_;
  QSpinBox* frames_;
  QSpinBox* width_;
  QSpinBox* height_;
  QComboBox* quality_;
  QDoubleSpinBox* fps_;
  QLineEdit* path_;
  ConfirmReplace confirm_;
  std::function<void(const QString&)> error_;
};

}  // namespace voxray::ui
