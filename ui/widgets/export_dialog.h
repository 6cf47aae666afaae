#pragma once
// Screenshot export (Ctrl+E): the 3D view at view size or a chosen resolution, a slice
// view, or the whole window, written as PNG, TIFF or EXR through writeImage. The file
// dialog asks before overwriting; annotations (values under the cursor, file name) are
// left out unless the user ticks them.
#include <array>

#include <QDialog>

#include "render_scheduler.h"

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace voxray::ui {

class SliceView;
class VolumeView;

class ExportDialog : public QDialog {
  Q_OBJECT
 public:
  ExportDialog(QWidget* window, RenderScheduler& scheduler, VolumeView& view,
               const std::array<SliceView*, 3>& slices);

 private:
  void save();
  QImage capture();  // empty on failure (a dialog has said why)

  QWidget* window_;
  RenderScheduler& scheduler_;
  VolumeView& view_;
  std::array<SliceView*, 3> slices_;
  QComboBox* what_;
  QComboBox* size_;
  QSpinBox* width_;
  QSpinBox* height_;
  QCheckBox* annotations_;
};

}  // namespace voxray::ui
