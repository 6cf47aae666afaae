// The Segments panel's Import and Export of segmentation files.
#include "segment_panel.h"

#include <filesystem>

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QColorDialog>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>

#include "coupling.h"
#include "gui_message.h"
#include "voxray/io/segment_output.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif
#include "segment_panel_helpers.h"

namespace voxray::ui {

bool SegmentPanel::exportTo(const QString& path) {
  if (m_.document.empty() || !m_.segmentation.active() ||
      m_.segmentation.segmentation().segments.empty()) {
    fail("Nothing to export", "Add a segment first.");
    return false;
  }
  std::error_code ec;
  const bool exists = std::filesystem::exists(path.toStdString(), ec);
  if (exists) {
    const bool yes =
        confirm_ ? confirm_(path)
                 : QMessageBox::question(
                       this, "Replace file?", QString("%1 already exists. Replace it?").arg(path),
                       QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
    if (!yes) return false;
  }
  try {
    writeSegmentationOutput(path.toStdString(), m_.segmentation.segmentation(),
                            *m_.document.volume(), exists);
    if (path.endsWith(".dcm", Qt::CaseInsensitive)) {
      lastSeg_ = path.toStdString();
      sendSeg_->setEnabled(true);
    }
  } catch (const std::exception& e) {
    fail("Export failed", e.what());
    return false;
  }
  return true;
}

bool SegmentPanel::importFrom(const QString& path) {
  if (m_.document.empty()) {
    fail("Cannot import", "Open the volume the segmentation belongs to first.");
    return false;
  }
#ifdef VOXRAY_HAS_SEGMENT_FILES
  try {
    m_.segmentation.load(readSegmentationFile(path.toStdString(), *m_.document.volume()),
                         *m_.document.volume());
    return true;
  } catch (const std::exception& e) {
    fail("Cannot import", e.what());
    return false;
  }
#else
  (void)path;
  fail("Cannot import", "This build reads no segmentation files (no DCMTK, nifti or teem).");
  return false;
#endif
}

void SegmentPanel::exportDialog() {
  QSettings s;
  const QString path = QFileDialog::getSaveFileName(
      this, "Export segments", s.value("lastSegmentFolder").toString(),
      "Surface (*.stl *.obj *.ply);;NIfTI label map (*.nii *.nii.gz);;3D Slicer (*.seg.nrrd);;"
      "DICOM SEG (*.dcm);;Raw labels (*.labels.raw)",
      nullptr, QFileDialog::DontConfirmOverwrite);  // exportTo asks
  if (path.isEmpty()) return;
  s.setValue("lastSegmentFolder", QFileInfo(path).absolutePath());
  exportTo(path);
}

void SegmentPanel::importDialog() {
  QSettings s;
  const QString path = QFileDialog::getOpenFileName(
      this, "Import segments", s.value("lastSegmentFolder").toString(),
      "Segmentations (*.nii *.nii.gz *.seg.nrrd *.nrrd *.dcm);;All files (*)");
  if (path.isEmpty()) return;
  s.setValue("lastSegmentFolder", QFileInfo(path).absolutePath());
  importFrom(path);
}

}  // namespace voxray::ui
