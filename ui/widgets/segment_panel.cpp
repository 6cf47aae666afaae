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

namespace voxray::ui {

namespace {

enum Column { kVisible, kColour, kName, kOpacity, kCategory, kType, kColumns };

// New segments' colours in turn: bone first, then colours far apart from it and each other.
glm::vec3 nextColour(size_t n) {
  static const glm::vec3 colours[] = {
      {0.95f, 0.90f, 0.75f}, {0.85f, 0.25f, 0.20f}, {0.30f, 0.70f, 0.30f}, {0.25f, 0.45f, 0.90f},
      {0.95f, 0.80f, 0.15f}, {0.80f, 0.35f, 0.80f}, {0.20f, 0.80f, 0.80f}, {0.95f, 0.55f, 0.15f}};
  return colours[n % (sizeof(colours) / sizeof(colours[0]))];
}

QColor toQColor(glm::vec3 c) { return QColor::fromRgbF(c.r, c.g, c.b); }

QString number(std::optional<double> v, int decimals = 1) {
  return v ? QString::number(*v, 'f', decimals) : QString();
}

QDoubleSpinBox* spin(double lo, double hi, double value, double step, int decimals,
                     const QString& suffix, const QString& tip) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(decimals);
  s->setSingleStep(step);
  s->setValue(value);
  s->setSuffix(suffix);
  s->setToolTip(tip);
  s->setKeyboardTracking(false);
  return s;
}

}  // namespace

SegmentPanel::SegmentPanel(AppModels& models, QWidget* parent) : QWidget(parent), m_(models) {
  setObjectName("segmentPanel");
  auto* layout = new QVBoxLayout(this);

  // The list and its buttons.
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton("Add");
  add->setObjectName("segmentAdd");
  add->setToolTip("Add a segment (the lowest free label) on the open volume");
  auto* remove = new QPushButton("Remove");
  remove->setObjectName("segmentRemove");
  remove->setToolTip("Remove the chosen segment and its voxels");
  undo_ = new QPushButton("Undo");
  undo_->setObjectName("segmentUndo");
  redo_ = new QPushButton("Redo");
  redo_->setObjectName("segmentRedo");
  for (QPushButton* b : {add, remove, undo_, redo_}) buttons->addWidget(b);
  layout->addLayout(buttons);
  list_ = new QTableWidget(0, kColumns);
  list_->setObjectName("segmentList");
  list_->setHorizontalHeaderLabels({"Show", "Colour", "Name", "Opacity %", "Category", "Type"});
  list_->setSelectionBehavior(QAbstractItemView::SelectRows);
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  list_->verticalHeader()->hide();
  list_->horizontalHeader()->setStretchLastSection(true);
  list_->setToolTip(
      "The segments: tick to show, double-click the colour to change it, edit the name, "
      "opacity and the category and type (free text)");
  list_->setMinimumHeight(120);
  layout->addWidget(list_);
  auto* files = new QHBoxLayout;
  auto* importButton = new QPushButton("Import…");
  importButton->setObjectName("segmentImport");
  importButton->setToolTip("Read a NIfTI, .seg.nrrd or DICOM SEG label map on the open volume");
  auto* exportButton = new QPushButton("Export…");
  exportButton->setObjectName("segmentExport");
  exportButton->setToolTip(
      "Write the segments: surfaces (.stl .obj .ply), label maps (.nii .nii.gz .seg.nrrd), "
      "DICOM SEG (.dcm) or raw labels (.labels.raw)");
  files->addWidget(importButton);
  files->addWidget(exportButton);
  layout->addLayout(files);

  // The tools in the slice views.
  auto* tools = new QGroupBox("Tools in the slice views");
  auto* form = new QFormLayout(tools);
  tool_ = new QComboBox;
  tool_->setObjectName("segmentTool");
  tool_->addItems(
      {"None (crosshair)", "Threshold", "Paint", "Erase", "Seeded region", "Scissors (3D view)"});
  tool_->setToolTip(
      "Threshold: preview the range in the views, Apply fills the segment; Paint/Erase: left "
      "drag; Seeded region: left click takes the range's region connected to it; Scissors: a "
      "left drag around part of the 3D view removes what lies behind it. Ctrl or Shift with a "
      "click moves the crosshair (or turns the 3D view) instead");
  form->addRow("Tool", tool_);
  radius_ = spin(0.5, 100.0, m_.segmentTools.settings().radiusMm, 0.5, 1, " mm",
                 "The brush's radius in millimetres");
  radius_->setObjectName("segmentRadius");
  sphere_ = new QCheckBox("3D sphere");
  sphere_->setObjectName("segmentSphere");
  sphere_->setToolTip("Paint and erase a ball (3D) instead of a disc in the view's slice");
  auto* brushRow = new QHBoxLayout;
  brushRow->addWidget(radius_);
  brushRow->addWidget(sphere_);
  form->addRow("Brush radius", brushRow);
  lo_ = spin(-100000, 100000, m_.segmentTools.settings().range.lo, 10, 0, "",
             "Lowest value taken (HU for CT)");
  lo_->setObjectName("segmentLo");
  hi_ = spin(-100000, 100000, m_.segmentTools.settings().range.hi, 10, 0, "",
             "Highest value taken (HU for CT)");
  hi_->setObjectName("segmentHi");
  auto* fromWindow = new QPushButton("From W/L");
  fromWindow->setObjectName("segmentFromWindow");
  fromWindow->setToolTip("Start the range from the slice views' window (level ± width/2)");
  auto* rangeRow = new QHBoxLayout;
  rangeRow->addWidget(lo_);
  rangeRow->addWidget(hi_);
  rangeRow->addWidget(fromWindow);
  form->addRow("Range", rangeRow);
  connectivity_ = new QComboBox;
  connectivity_->addItems({"6 (faces)", "26 (faces, edges, corners)"});
  connectivity_->setToolTip("Which neighbours join a seeded region and an island");
  form->addRow("Connectivity", connectivity_);
  overwrite_ = new QCheckBox("Take other segments' voxels");
  overwrite_->setToolTip("Painting and thresholds also take voxels that other segments hold");
  form->addRow("", overwrite_);
  auto* apply = new QPushButton("Apply threshold");
  apply->setObjectName("segmentApplyThreshold");
  apply->setToolTip("Every voxel in the range becomes the chosen segment's (one undo step)");
  preview_ = new QLabel;
  preview_->setObjectName("segmentPreview");
  preview_->setToolTip("The threshold's voxels in the axial view's slice");
  auto* applyRow = new QHBoxLayout;
  applyRow->addWidget(apply);
  applyRow->addWidget(preview_, 1);
  form->addRow("", applyRow);
  layout->addWidget(tools);

  // Operations on the chosen segment.
  auto* ops = new QGroupBox("Operations on the chosen segment");
  auto* opsForm = new QFormLayout(ops);
  operation_ = new QComboBox;
  operation_->setObjectName("segmentOperation");
  for (MaskOperation op : {MaskOperation::KeepLargest, MaskOperation::RemoveSmall,
                           MaskOperation::FillHoles, MaskOperation::Margin, MaskOperation::Median,
                           MaskOperation::Closing, MaskOperation::Opening})
    operation_->addItem(toString(op), int(op));
  operation_->setToolTip("Each operation is one undo step");
  value_ = spin(-100, 100000, 2.0, 0.5, 1, "",
                "Remove small islands: the smallest kept in mm³; Margin: mm (> 0 grows, < 0 "
                "shrinks); smoothing: the kernel's diameter in mm");
  value_->setObjectName("segmentOperationValue");
  auto* runOp = new QPushButton("Apply");
  runOp->setObjectName("segmentApplyOperation");
  auto* opRow = new QHBoxLayout;
  opRow->addWidget(operation_, 1);
  opRow->addWidget(value_);
  opRow->addWidget(runOp);
  opsForm->addRow(opRow);
  logicalOp_ = new QComboBox;
  logicalOp_->addItems({"Add", "Subtract", "Intersect"});
  logicalOp_->setToolTip("The chosen segment with another: add takes the other's voxels");
  other_ = new QComboBox;
  other_->setObjectName("segmentOther");
  other_->setToolTip("The other segment");
  auto* runLogical = new QPushButton("Apply");
  runLogical->setObjectName("segmentApplyLogical");
  auto* logicalRow = new QHBoxLayout;
  logicalRow->addWidget(logicalOp_);
  logicalRow->addWidget(other_, 1);
  logicalRow->addWidget(runLogical);
  opsForm->addRow(logicalRow);
  layout->addWidget(ops);

  // The 3D view (dvr).
  auto* view3d = new QGroupBox("3D view (dvr)");
  auto* form3d = new QFormLayout(view3d);
  mask3d_ = new QComboBox;
  mask3d_->setObjectName("segmentMask3d");
  mask3d_->addItems({"Off", "Show only", "Hide"});
  mask3d_->setToolTip(
      "The chosen segment in the 3D view: show only what segments chosen so cover, or hide "
      "what they cover (Show and Hide exclude each other)");
  form3d->addRow("Mask", mask3d_);
  blend_ = new QSlider(Qt::Horizontal);
  blend_->setObjectName("segmentBlend");
  blend_->setRange(0, 100);
  blend_->setToolTip("How strongly a visible segment's colour replaces the transfer function's");
  form3d->addRow("Colour blend", blend_);
  layout->addWidget(view3d);

  // Statistics.
  auto* statsBox = new QGroupBox("Statistics");
  auto* statsLayout = new QVBoxLayout(statsBox);
  stats_ = new QTableWidget(0, 8);
  stats_->setObjectName("segmentStats");
  stats_->setHorizontalHeaderLabels(
      {"Segment", "Voxels", "Volume mL", "Mean", "SD", "Min", "Max", "Median"});
  stats_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  stats_->verticalHeader()->hide();
  stats_->setMinimumHeight(90);
  stats_->setToolTip("Each segment's voxels, volume and the values inside it (Update counts)");
  statsLayout->addWidget(stats_);
  auto* statsButtons = new QHBoxLayout;
  auto* update = new QPushButton("Update");
  update->setObjectName("segmentStatsUpdate");
  update->setToolTip("Count the segments' voxels and the values inside them");
  auto* copy = new QPushButton("Copy");
  copy->setToolTip("Copy the table (tab-separated, pastes into a spreadsheet)");
  auto* csv = new QPushButton("Save CSV…");
  csv->setToolTip("Write the statistics as a CSV file");
  for (QPushButton* b : {update, copy, csv}) statsButtons->addWidget(b);
  statsLayout->addLayout(statsButtons);
  layout->addWidget(statsBox);
  layout->addStretch(1);

  connect(add, &QPushButton::clicked, this, [this] { addSegment(); });
  connect(remove, &QPushButton::clicked, this, [this] {
    if (const uint8_t l = currentLabel()) m_.segmentation.removeSegment(l);
  });
  connect(undo_, &QPushButton::clicked, this, [this] { m_.segmentation.undo(); });
  connect(redo_, &QPushButton::clicked, this, [this] { m_.segmentation.redo(); });
  connect(list_, &QTableWidget::cellDoubleClicked, this, [this](int row, int column) {
    if (column == kColour) chooseColour(row);
  });
  connect(list_, &QTableWidget::cellChanged, this, [this](int row, int column) {
    if (!refreshing_) editCell(row, column);
  });
  connect(list_, &QTableWidget::itemSelectionChanged, this, [this] {
    if (refreshing_) return;
    setTools([this](SegmentToolSettings& s) { s.label = currentLabel(); });
    refreshTools();
  });
  connect(importButton, &QPushButton::clicked, this, [this] { importDialog(); });
  connect(exportButton, &QPushButton::clicked, this, [this] { exportDialog(); });
  connect(tool_, &QComboBox::currentIndexChanged, this,
          [this](int i) { setTools([i](SegmentToolSettings& s) { s.tool = SegmentTool(i); }); });
  connect(radius_, &QDoubleSpinBox::valueChanged, this,
          [this](double v) { setTools([v](SegmentToolSettings& s) { s.radiusMm = v; }); });
  connect(sphere_, &QCheckBox::toggled, this,
          [this](bool on) { setTools([on](SegmentToolSettings& s) { s.sphere = on; }); });
  connect(lo_, &QDoubleSpinBox::valueChanged, this,
          [this](double v) { setTools([v](SegmentToolSettings& s) { s.range.lo = v; }); });
  connect(hi_, &QDoubleSpinBox::valueChanged, this,
          [this](double v) { setTools([v](SegmentToolSettings& s) { s.range.hi = v; }); });
  connect(fromWindow, &QPushButton::clicked, this, [this] {
    const HuRange r = rangeFromWindow(m_.windowLevel.value());
    setTools([r](SegmentToolSettings& s) { s.range = r; });
  });
  connect(connectivity_, &QComboBox::currentIndexChanged, this, [this](int i) {
    setTools([i](SegmentToolSettings& s) {
      s.connectivity = i == 1 ? Connectivity::Full26 : Connectivity::Faces6;
    });
  });
  connect(overwrite_, &QCheckBox::toggled, this,
          [this](bool on) { setTools([on](SegmentToolSettings& s) { s.overwriteOthers = on; }); });
  connect(apply, &QPushButton::clicked, this, [this] {
    if (m_.document.empty()) return;
    try {
      applyThreshold(m_.segmentation, *m_.document.volume(), m_.segmentTools.settings());
    } catch (const std::exception& e) {
      fail("Cannot apply the threshold", e.what());
    }
  });
  connect(runOp, &QPushButton::clicked, this, [this] { runOperation(); });
  connect(runLogical, &QPushButton::clicked, this, [this] { this->runLogical(); });
  connect(mask3d_, &QComboBox::currentIndexChanged, this, [this](int i) {
    const uint8_t label = currentLabel();
    if (!label || refreshing_) return;
    m_.render.update(kAppearance, [&](RenderParams& p) {
      p.segmentMask = withMaskChoice(p.segmentMask, label, MaskChoice(i));
    });
  });
  connect(blend_, &QSlider::valueChanged, this, [this](int v) {
    if (refreshing_) return;
    m_.render.update(kAppearance, [v](RenderParams& p) { p.segmentBlend = v / 100.0; });
  });
  connect(update, &QPushButton::clicked, this, [this] { updateStatistics(); });
  connect(copy, &QPushButton::clicked, this,
          [this] { QApplication::clipboard()->setText(statisticsText()); });
  connect(csv, &QPushButton::clicked, this, [this] { saveCsv(); });

  onModelChange<>(this, m_.segmentation.changed, [this] { refreshList(); });
  onModelChange<>(this, m_.segmentTools.changed, [this] { refreshTools(); });
  onModelChange<>(this, m_.crosshair.changed, [this] { refreshTools(); });
  onModelChange<>(this, m_.document.changed, [this] { refreshTools(); });
  onModelChange<unsigned>(this, m_.render.changed, [this](unsigned what) {
    if (what & kAppearance) refreshTools();
  });
  refreshList();
  refreshTools();
}

void SegmentPanel::fail(const QString& title, const QString& message) {
  const QString text = QString::fromStdString(guiMessage(message.toStdString()));
  if (error_)
    error_(title, text);
  else
    QMessageBox::warning(this, title, text);
}

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

void SegmentPanel::refreshTools() {
  refreshing_ = true;
  const SegmentToolSettings& s = m_.segmentTools.settings();
  {
    const QSignalBlocker b1(tool_), b2(radius_), b3(sphere_), b4(lo_), b5(hi_), b6(connectivity_),
        b7(overwrite_);
    tool_->setCurrentIndex(int(s.tool));
    radius_->setValue(s.radiusMm);
    sphere_->setChecked(s.sphere);
    lo_->setValue(s.range.lo);
    hi_->setValue(s.range.hi);
    connectivity_->setCurrentIndex(s.connectivity == Connectivity::Full26 ? 1 : 0);
    overwrite_->setChecked(s.overwriteOthers);
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
  refreshing_ = false;
}

void SegmentPanel::setTools(const std::function<void(SegmentToolSettings&)>& edit) {
  SegmentToolSettings s = m_.segmentTools.settings();
  edit(s);
  m_.segmentTools.set(s);
}

void SegmentPanel::chooseColour(int row) {
  const uint8_t label = uint8_t(list_->item(row, kName)->data(Qt::UserRole).toInt());
  const Segment* s = m_.segmentation.segmentation().find(label);
  if (!s) return;
  const QColor c = QColorDialog::getColor(toQColor(s->colour), this, "Segment colour");
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

void SegmentPanel::updateStatistics() {
  lastStats_.clear();
  if (!m_.document.empty() && m_.segmentation.active()) {
    try {
      lastStats_ = allSegmentStats(m_.segmentation.segmentation(), *m_.document.volume());
    } catch (const std::exception& e) {
      fail("Cannot count the segments", e.what());
    }
  }
  stats_->setRowCount(int(lastStats_.size()));
  for (int row = 0; row < int(lastStats_.size()); ++row) {
    const SegmentStats& s = lastStats_[size_t(row)];
    const QStringList cells = {QString::fromStdString(s.name),
                               QString::number(s.voxels),
                               QString::number(s.volumeMl, 'f', 3),
                               number(s.mean),
                               number(s.sd),
                               number(s.min),
                               number(s.max),
                               number(s.median)};
    for (int c = 0; c < cells.size(); ++c) stats_->setItem(row, c, new QTableWidgetItem(cells[c]));
  }
}

QString SegmentPanel::statisticsText() const {
  QStringList lines;
  QStringList header;
  for (int c = 0; c < stats_->columnCount(); ++c) header << stats_->horizontalHeaderItem(c)->text();
  lines << header.join('\t');
  for (int row = 0; row < stats_->rowCount(); ++row) {
    QStringList cells;
    for (int c = 0; c < stats_->columnCount(); ++c)
      cells << (stats_->item(row, c) ? stats_->item(row, c)->text() : QString());
    lines << cells.join('\t');
  }
  return lines.join('\n') + '\n';
}

void SegmentPanel::saveCsv() {
  if (lastStats_.empty()) updateStatistics();
  QSettings s;
  const QString path = QFileDialog::getSaveFileName(
      this, "Save statistics", s.value("lastSegmentFolder").toString(), "CSV (*.csv)");
  if (path.isEmpty()) return;  // the dialog asked before replacing
  QFile f(path);
  const std::string csv = statsCsv(lastStats_);
  if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
      f.write(csv.data(), qint64(csv.size())) != qint64(csv.size()))
    fail("Cannot save the statistics",
         "Cannot write " + path + ": check the folder and free space.");
}

QDockWidget* makeSegmentDock(AppModels& models, SegmentPanel** panel) {
  auto* dock = new QDockWidget("Segments");
  dock->setObjectName("segmentDock");
  auto* p = new SegmentPanel(models);
  auto* scroll = new QScrollArea;
  scroll->setWidgetResizable(true);
  scroll->setWidget(p);
  dock->setWidget(scroll);
  if (panel) *panel = p;
  return dock;
}

}  // namespace voxray::ui
