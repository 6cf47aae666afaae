// The Segments panel's tools: the settings shown and set.
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

void SegmentPanel::refreshTools() {
  refreshing_ = true;
  const SegmentToolSettings& s = m_.segmentTools.settings();
  {
    const QSignalBlocker b1(tool_), b2(radius_), b3(sphere_), b4(lo_), b5(hi_), b6(connectivity_),
        b7(overwrite_), b8(scissorsKeep_);
    tool_->setCurrentIndex(int(s.tool));
    radius_->setValue(s.radiusMm);
    sphere_->setChecked(s.sphere);
    lo_->setValue(s.range.lo);
    hi_->setValue(s.range.hi);
    connectivity_->setCurrentIndex(s.connectivity == Connectivity::Full26 ? 1 : 0);
    overwrite_->setChecked(s.overwriteOthers);
    scissorsKeep_->setChecked(s.scissorsKeep);
  }
  if (s.label && s.label != currentLabel()) selectLabel(s.label);  // a pick in the 3D view
  QString text;
  if (!m_.document.empty()) {
    const Volume& v = *m_.document.volume();
    const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
    try {
      const size_t n = previewCount(v, axial.nAxis, m_.crosshair.sliceOf(axial), s.range);
      text = QString("%1 voxels (axial slice)").arg(n);
    } catch (const std::exception&) {
      text = "Give a range with low ≤ high";
    }
  }
  preview_->setText(text);
  const RenderParams& p = m_.render.params();
  mask3d_->setCurrentIndex(int(maskChoiceOf(p.segmentMask, s.label)));
  blend_->setValue(int(std::lround(p.segmentBlend * 100)));
  int tf = 0;  // Volume's
  if (auto it = p.segmentTfs.find(s.label); it != p.segmentTfs.end()) {
    tf = segTf_->count() - 1;  // Custom, unless a preset gives this table
    for (int i = 1; i + 1 < segTf_->count(); ++i)
      if (findPreset(segTf_->itemData(i).toString().toStdString()).tf.points == it->second) tf = i;
  }
  segTf_->setCurrentIndex(tf);
  refreshing_ = false;
}

void SegmentPanel::setTools(const std::function<void(SegmentToolSettings&)>& edit) {
  SegmentToolSettings s = m_.segmentTools.settings();
  edit(s);
  m_.segmentTools.set(s);
}

}  // namespace voxray::ui
