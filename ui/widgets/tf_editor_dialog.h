#pragma once
// The transfer-function editor (issue 35): a window beside the 3D view with the curve over the
// volume's histogram (TfCurveView), the selected point's numbers, the curve type, the opacity
// unit distance, the HU axis, and files (Voxray .json, 3D Slicer .vp). Edits render at once.
#include <memory>

#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>

#include "app_models.h"
#include "background_task.h"
#include "tf_curve_view.h"
#include "tf_editor_model.h"

namespace voxray::ui {

class TfEditorDialog : public QDialog {
 public:
  TfEditorDialog(AppModels& models, QWidget* parent = nullptr);
  ~TfEditorDialog() override;

  TfEditorModel& model() { return *model_; }
  TfCurveView& curve() { return *curve_; }
  // Reads FILE into the editor; a bad file leaves the transfer function as it was and
  // returns the message (empty on success). The Load button shows it in a box.
  // A 3D Slicer preset list (.xml) asks which preset through choosePreset (a list box by
  // default; tests answer it); no answer changes nothing.
  QString loadFile(const QString& file);
  std::function<QString(const QStringList& names)> choosePreset;
  QString saveFile(const QString& file);  // same for writing
  // The histogram's count is done (tests wait for it).
  bool histogramReady() const { return histogramReady_; }

 private:
  void countHistogram();
  void showSelection();
  void fitVisible();
  void fitVolume();

  AppModels& models_;
  std::unique_ptr<TfEditorModel> model_;
  TfCurveView* curve_;
  QObject* modelLinks_;  // the dialog's connections to model_
  QComboBox* curveType_;
  QDoubleSpinBox *unit_, *huLo_, *huHi_, *pointHu_, *pointOpacity_;
  QPushButton *pointColor_, *undo_, *redo_;
  QLabel* status_;
  bool histogramReady_ = false;
  BackgroundTask histogramTask_;
};

}  // namespace voxray::ui
