// The Segments panel's list: choosing, adding, refreshing and editing the segments.
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
#include <QSignalBlocker>
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

uint8_t SegmentPanel::currentLabel() const {
  const int row = list_->currentRow();
  if (row < 0 || !list_->item(row, kName)) return 0;
  return uint8_t(list_->item(row, kName)->data(Qt::UserRole).toInt());
}

void SegmentPanel::selectLabel(uint8_t label) {
  for (int row = 0; row < list_->rowCount(); ++row)
    if (list_->item(row, kName) && list_->item(row, kName)->data(Qt::UserRole).toInt() == label)
      list_->selectRow(row);
}

void SegmentPanel::ensureActive() {
  if (m_.segmentation.active() || m_.document.empty()) return;
  m_.segmentation.reset(*m_.document.volume());
}

void SegmentPanel::addSegment() {
  if (m_.document.empty()) return fail("Cannot add a segment", "Open a volume first.");
  ensureActive();
  const size_t n = m_.segmentation.segmentation().segments.size();
  try {
    const uint8_t label =
        m_.segmentation.addSegment("Segment " + std::to_string(n + 1), nextColour(n));
    // A removed segment's own transfer function stays with its label (undoing the removal
    // brings both back); a new segment given that label starts with the volume's.
    if (m_.render.params().segmentTfs.count(label))
      m_.render.update(kAppearance, [label](RenderParams& p) { p.segmentTfs.erase(label); });
    selectLabel(label);
  } catch (const std::exception& e) {
    fail("Cannot add a segment", e.what());
  }
}

void SegmentPanel::refreshList() {
  refreshing_ = true;
  const uint8_t current = m_.segmentTools.settings().label;
  const auto& segments = m_.segmentation.segmentation().segments;
  list_->setRowCount(int(segments.size()));
  other_->clear();
  for (int row = 0; row < int(segments.size()); ++row) {
    const Segment& s = segments[size_t(row)];
    auto* visible = new QTableWidgetItem;
    visible->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
    visible->setCheckState(s.visible ? Qt::Checked : Qt::Unchecked);
    list_->setItem(row, kVisible, visible);
    auto* colour = new QTableWidgetItem;
    colour->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    // A swatch (decoration): it stays visible in a selected row, where a background would not.
    colour->setData(Qt::DecorationRole, toQColor(s.colour));
    list_->setItem(row, kColour, colour);
    auto* name = new QTableWidgetItem(QString::fromStdString(s.name));
    name->setData(Qt::UserRole, int(s.label));
    list_->setItem(row, kName, name);
    list_->setItem(row, kOpacity,
                   new QTableWidgetItem(QString::number(std::lround(s.opacity * 100))));
    list_->setItem(row, kCategory,
                   new QTableWidgetItem(QString::fromStdString(s.category.meaning)));
    list_->setItem(row, kType, new QTableWidgetItem(QString::fromStdString(s.type.meaning)));
    setDisplay3dCell(row, s);
    other_->addItem(QString::fromStdString(s.name), int(s.label));
  }
  selectLabel(current);
  if (list_->currentRow() < 0 && !segments.empty()) list_->selectRow(int(segments.size()) - 1);
  undo_->setEnabled(m_.segmentation.canUndo());
  redo_->setEnabled(m_.segmentation.canRedo());
  const std::string undo = m_.segmentation.undoText(), redo = m_.segmentation.redoText();
  undo_->setToolTip(undo.empty() ? "Undo the last segment edit (none yet)"
                                 : QString::fromStdString(undo));
  redo_->setToolTip(redo.empty() ? "Redo the segment edit last undone (none)"
                                 : QString::fromStdString(redo));
  refreshing_ = false;
  // The tools follow the chosen row (a removed segment's label goes).
  setTools([this](SegmentToolSettings& s) { s.label = currentLabel(); });
}

// The row's "3D" choice: a combo box kept across refreshes (a refresh inside its own signal
// must not delete it), showing the segment's display.
void SegmentPanel::setDisplay3dCell(int row, const Segment& s) {
  auto* box = qobject_cast<QComboBox*>(list_->cellWidget(row, kDisplay3d));
  if (!box) {
    box = new QComboBox;
    box->setObjectName("segmentDisplay3d");
    // In the order of Segment::Display3d.
    box->addItem("In volume", int(Segment::Display3d::Volume));
    box->addItem("Surface", int(Segment::Display3d::Surface));
    box->addItem("Hidden", int(Segment::Display3d::Hidden));
    box->setToolTip(
        "How the segment shows in 3D: its colour inside the volume rendering (dvr), a smooth "
        "surface drawn over the dvr, or hidden there (the slice views still show it)");
    list_->setCellWidget(row, kDisplay3d, box);
    connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, box](int index) {
      if (refreshing_ || index < 0) return;
      const uint8_t label = uint8_t(box->property("label").toInt());
      if (!m_.segmentation.segmentation().find(label)) return;
      try {
        m_.segmentation.setDisplay3d(label, Segment::Display3d(box->itemData(index).toInt()));
      } catch (const std::exception& e) {
        fail("Segment 3D display", e.what());
      }
    });
  }
  const QSignalBlocker block(box);
  box->setProperty("label", int(s.label));
  box->setCurrentIndex(box->findData(int(s.display3d)));
}

void SegmentPanel::chooseColour(int row) {
  const uint8_t label = uint8_t(list_->item(row, kName)->data(Qt::UserRole).toInt());
  const Segment* s = m_.segmentation.segmentation().find(label);
  if (!s) return;
  const QColor c = chooseColour_
                       ? chooseColour_(toQColor(s->colour))
                       : QColorDialog::getColor(toQColor(s->colour), this, "Segment colour");
  if (c.isValid())
    m_.segmentation.setColour(label, {float(c.redF()), float(c.greenF()), float(c.blueF())});
}

void SegmentPanel::editCell(int row, int column) {
  QTableWidgetItem* nameItem = list_->item(row, kName);
  QTableWidgetItem* item = list_->item(row, column);
  if (!nameItem || !item) return;
  const uint8_t label = uint8_t(nameItem->data(Qt::UserRole).toInt());
  const Segment* s = m_.segmentation.segmentation().find(label);
  if (!s) return;
  try {
    switch (column) {
      case kVisible:
        m_.segmentation.setVisible(label, item->checkState() == Qt::Checked);
        break;
      case kName:
        m_.segmentation.rename(label, item->text().toStdString());
        break;
      case kOpacity: {
        bool ok = false;
        const double percent = item->text().toDouble(&ok);
        if (!ok) {
          refreshList();
          return fail("Segment opacity", "Give the opacity in percent, 0 to 100.");
        }
        m_.segmentation.setOpacity(label, float(percent / 100.0));
        break;
      }
      case kCategory:
      case kType: {
        // Free text: the meaning alone, no code (a coded entry the user retypes keeps its code).
        Segment::Code category = s->category, type = s->type;
        Segment::Code& code = column == kCategory ? category : type;
        const std::string text = item->text().toStdString();
        if (text != code.meaning) code = {"", "", text};
        m_.segmentation.setCodes(label, category, type);
        break;
      }
      default:
        break;
    }
  } catch (const std::exception& e) {
    fail("Cannot change the segment", e.what());
  }
}

}  // namespace voxray::ui
