#pragma once
// The Fusion group (issue 36): a second volume over the first in the slice views and the 3D
// view, its colour map, window (in the overlay's unit, SUV for a PET with one), opacity and
// on/off. Thin: the overlay and its settings are FusionModel's; the slice views draw it
// (SliceView::setFusion), the 3D view raycasts it with the volume (RenderScheduler::setOverlay).
#include <map>
#include <string>

#include <QObject>
#include <QWidget>

#include "app_models.h"
#include "voxray/io/load.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace voxray::ui {

class LoadController;

class FusionPanel : public QWidget {
  Q_OBJECT
 public:
  explicit FusionPanel(FusionModel& fusion, QWidget* parent = nullptr);

  QCheckBox* onBox() const { return on_; }
  QComboBox* colormapBox() const { return map_; }
  QDoubleSpinBox* loBox() const { return lo_; }
  QDoubleSpinBox* hiBox() const { return hi_; }
  QSlider* opacitySlider() const { return opacity_; }
  // A 4D overlay's own time point (time_follow.h): off while it follows the study's.
  QSpinBox* timeBox() const { return time_; }

 signals:
  void openRequested();  // the "Open overlay volume…" button

 private:
  void showModel();  // the model's overlay and settings into the controls
  void apply();      // the controls into the model (a bad window is said, not taken)

  FusionModel& fusion_;
  QLabel* name_;
  QLabel* error_;
  QCheckBox* on_;
  QComboBox* map_;
  QDoubleSpinBox *lo_, *hi_;
  QSlider* opacity_;
  QSpinBox* time_;
};

// Loads an overlay on a load thread of its own (the study's loader stays free) and makes it
// MODELS' fusion overlay, over the document's volume.
class OverlayLoader : public QObject {
  Q_OBJECT
 public:
  OverlayLoader(AppModels& models, QWidget* dialogParent);
  void load(const std::string& input, const LoadOptions& options = {});

 signals:
  // The overlay is shown; WARNINGS: what the user must know (no shared Frame of Reference).
  void opened(const QString& name, const QStringList& warnings);
  void failed(const QString& message);

 private:
  AppModels& models_;
  LoadController* loader_;
  std::string sourcePath_;
  std::map<std::string, std::string> sourceFlags_;
};

// Asks for any input the loader reads: a volume file, or any file of a DICOM series (its
// folder is opened). Empty when cancelled.
std::string askVolumeInput(QWidget* parent, const QString& title);

}  // namespace voxray::ui
