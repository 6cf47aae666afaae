// The Segments panel's operations on the chosen segment and between two.
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

void SegmentPanel::runOperation() {
  try {
    applyOperation(m_.segmentation, currentLabel(),
                   MaskOperation(operation_->currentData().toInt()), value_->value(),
                   m_.segmentTools.settings().connectivity);
  } catch (const std::exception& e) {
    fail("Cannot apply the operation", e.what());
  }
}

void SegmentPanel::runLogical() {
  try {
    applyLogical(m_.segmentation, currentLabel(), uint8_t(other_->currentData().toInt()),
                 LogicalOp(logicalOp_->currentIndex()));
  } catch (const std::exception& e) {
    fail("Cannot apply the operation", e.what());
  }
}

}  // namespace voxray::ui
