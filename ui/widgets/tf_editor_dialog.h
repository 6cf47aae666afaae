#pragma once
// The transfer-function editor (issue 35): a window beside the 3D view with the curve over the
// volume's histogram (TfCurveView), the selected point's numbers, the curve type, the opacity
// unit distance, the HU axis, and files (Voxray .json, 3D Slicer .vp). Edits render at once.
// A second tab edits the 2D transfer function (Tf2dView over the value x |gradient|
// histogram, counted in the background the first time the tab shows a volume); a third is
// the preset gallery (TfGalleryView: pictures of every preset on the volume). The Segments
// panel opens it on a segment's own table (editTable).
#include <memory>

#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>

#include "app_models.h"
#include "background_task.h"
#include "tf2d_view.h"
#include "tf_curve_view.h"
#include "tf_editor_model.h"
#include "tf_gallery_view.h"

namespace voxray::ui {

class TfEditorDialog : public QDialog {
 public:
  // SCHEDULER renders the preset gallery's pictures (none: the tiles stay empty).
  TfEditorDialog(AppModels& models, RenderScheduler* scheduler, QWidget* parent = nullptr);
  ~TfEditorDialog() override;

  TfEditorModel& model() { return *model_; }
  // Which table the editor shapes: the volume's (0; View → Transfer function editor) or
  // segment LABEL's own (the Segments panel's TF… Edit), as TfEditorModel::setTarget. The 2D
  // and preset tabs and the opacity unit distance are the volume's: off for a segment.
  void editTable(uint8_t label);
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
  Tf2dView& tf2d() { return *tf2d_; }
  QTabWidget& tabs() { return *tabs_; }
  // The 2D histogram's count is done (tests wait for it).
  bool tf2dHistogramReady() const { return tf2dReady_; }
  TfGalleryView& gallery() { return *gallery_; }
  // The gallery shows the built-in presets and DIR's (read again), the tab names DIR and
  // what could not be read there. Not remembered (the Folder… button remembers its choice).
  void usePresetFolder(const QString& dir);

 private:
  void countHistogram();
  void showSelection();
  void fitCurve();
  void fitVolume();
  QWidget* make2dTab();
  QWidget* makePresetsTab(RenderScheduler* scheduler);  // tf_gallery_tab.cpp
  void count2dHistogram();
  void show2dSelection();

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
  QTabWidget* tabs_;
  Tf2dView* tf2d_;
  QDoubleSpinBox *tf2dHu0_, *tf2dHu1_, *tf2dG0_, *tf2dG1_, *tf2dOpacity_, *tf2dSoft_;
  QPushButton* tf2dColor_;
  QLabel* tf2dStatus_;
  bool tf2dReady_ = false;
  // The volume the 2D histogram is of (or being counted); weak, so that a new volume at a
  // freed one's address is never taken for it.
  std::weak_ptr<const Volume> tf2dCounted_;
  BackgroundTask tf2dTask_;
  TfGalleryView* gallery_;
  QLabel *galleryStatus_, *galleryFolder_;
};

}  // namespace voxray::ui
