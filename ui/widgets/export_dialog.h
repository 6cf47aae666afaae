#pragma once
// Screenshot export (Ctrl+E): the 3D view at view size or a chosen resolution, a slice
// view, or the whole window, written as PNG, TIFF or EXR through writeImage, or (.dcm) as a
// DICOM Secondary Capture in the volume's study, which "Send to" then sends to a PACS node
// in the background (the dialog closes once the node took it, else says why). An existing
// file is replaced only after a yes (resolveExportTarget, asked with the final name); the
// cursor readout is left out unless the user ticks it. The 3D view exports its rendered
// pixels only, never the handles drawn over them; a slice view does too with "Overlays"
// unticked (SliceView::cleanImage: the slice's own pixels, segments and fusion optional).
#include <array>
#include <functional>
#include <memory>

#include <QDialog>

#include "export_target.h"
#include "render_scheduler.h"
#include "voxray/io/volume.h"

#ifdef VOXRAY_HAS_DICOM
#include "pacs_browser.h"
#endif

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace voxray::ui {

class SliceView;
class VolumeView;

class ExportDialog : public QDialog {
  Q_OBJECT
 public:
  ExportDialog(QWidget* window, RenderScheduler& scheduler, VolumeView& view,
               const std::array<SliceView*, 3>& slices);
  ~ExportDialog() override;

  // The study a Secondary Capture joins (the shown volume's).
  void setStudy(const StudyIdentity& study) { study_ = study; }

  // What the Save button asks for; tests replace the file and message dialogs.
  void setPathChooser(std::function<QString()> choose) { choose_ = std::move(choose); }
  void setConfirmOverwrite(ConfirmOverwrite confirm) { confirm_ = std::move(confirm); }
  void setErrorSink(std::function<void(const QString&)> sink) { error_ = std::move(sink); }
  // Writes the current choice to CHOSEN (".png" added when it has no suffix). False when
  // nothing was written: the user kept an existing file, or capturing or writing failed.
  bool exportTo(const QString& chosen);
  // After exportTo wrote a .dcm: sends it to the node in "Send to" (if any) in the
  // background; sent() or the error sink follows. False when nothing is to be sent.
  bool sendExported();
  bool sending() const { return sending_; }
  // While sending, Cancel (the button, Esc, closing) cancels the send and keeps the dialog
  // open with the file; otherwise it closes the dialog.
  void reject() override;

 signals:
  void sent();
  void sendCancelled();

 private:
  void save();
  QString askPath();
  bool askOverwrite(const std::string& path);
  QImage capture();         // empty on failure (a dialog has said why)
  bool cleanSlice() const;  // a slice view without overlays is chosen
  // The size of what choice WHAT (the capture box's index) writes at its own size.
  QSize capturedSize(int what) const;

  QWidget* window_;
  RenderScheduler& scheduler_;
  VolumeView& view_;
  std::array<SliceView*, 3> slices_;
  QComboBox* what_;
  QComboBox* size_;
  QSpinBox* width_;
  QSpinBox* height_;
  QCheckBox* annotations_;
  QCheckBox* studyText_;
  QCheckBox* overlays_;  // a slice view as shown (ticked) or its clean image
  QCheckBox* layers_;    // the clean image with the segments and the fused overlay
  QComboBox* sendTo_;
  QLabel* status_;
  std::string written_;  // the last file exportTo wrote
  bool sending_ = false;
  StudyIdentity study_;
  QSize chosen_;  // the chosen resolution, kept while the fields show another capture's size
  std::function<QString()> choose_;
  ConfirmOverwrite confirm_;
  std::function<void(const QString&)> error_;
#ifdef VOXRAY_HAS_DICOM
  std::unique_ptr<PacsBrowser> pacs_;  // last member: its thread stops before the rest goes
#endif
};

}  // namespace voxray::ui
