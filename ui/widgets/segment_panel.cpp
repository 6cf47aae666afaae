// The Segments panel: its widgets and their connections, errors, and the dock around it.
#include "segment_panel.h"

#include <filesystem>
#include <memory>

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
#include <QTimer>
#include <QVBoxLayout>

#include "coupling.h"
#include "gui_message.h"
#include "voxray/io/segment_output.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif
#include "segment_panel_helpers.h"

namespace voxray::ui {

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
  list_->setHorizontalHeaderLabels(
      {"Show", "Colour", "Name", "Opacity %", "Category", "Type", "3D"});
  list_->setSelectionBehavior(QAbstractItemView::SelectRows);
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  list_->verticalHeader()->hide();
  list_->horizontalHeader()->setStretchLastSection(true);
  list_->setToolTip(
      "The segments: tick to show, double-click the colour to change it, edit the name, "
      "opacity and the category and type (free text); 3D: in the volume's colours, as a "
      "smooth surface, or hidden in the 3D view");
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
  sendSeg_ = new QPushButton("Send SEG to PACS…");
  sendSeg_->setObjectName("segmentSendSeg");
  sendSeg_->setToolTip("Send the DICOM SEG last exported (Export… as .dcm) to a PACS node");
  sendSeg_->setEnabled(false);
  files->addWidget(sendSeg_);
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
  auto* fromTf = new QPushButton("From TF");
  fromTf->setObjectName("segmentFromTf");
  fromTf->setToolTip(
      "Start the range from what the 3D view shows: the transfer function's opaque range "
      "(iso: the surface's range)");
  rangeRow->addWidget(fromTf);
  form->addRow("Range", rangeRow);
  connectivity_ = new QComboBox;
  connectivity_->addItems({"6 (faces)", "26 (faces, edges, corners)"});
  connectivity_->setToolTip("Which neighbours join a seeded region and an island");
  form->addRow("Connectivity", connectivity_);
  overwrite_ = new QCheckBox("Take other segments' voxels");
  overwrite_->setToolTip("Painting and thresholds also take voxels that other segments hold");
  form->addRow("", overwrite_);
  scissorsKeep_ = new QCheckBox("Scissors keep only inside");
  scissorsKeep_->setObjectName("segmentScissorsKeep");
  scissorsKeep_->setToolTip(
      "Scissors in the 3D view keep only what lies behind the lasso (e.g. the head without the "
      "table) instead of removing it");
  form->addRow("", scissorsKeep_);
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
  // Per-segment transfer functions (issue 35): a dvr preset for the chosen segment; Custom
  // only shows a table no preset gives (from a session or voxray-cli), it sets nothing.
  segTf_ = new QComboBox;
  segTf_->setObjectName("segmentTf");
  segTf_->addItem("Volume's", QString());
  for (const Preset& preset : builtinPresets())
    if (preset.mode == "dvr")
      segTf_->addItem(QString::fromStdString(preset.name), QString::fromStdString(preset.name));
  segTf_->addItem("Custom", QString("\n"));
  segTf_->setToolTip(
      "The chosen segment's own transfer function in the 3D view, used where it lies instead "
      "of the volume's (and of its colour); Volume's: none. Edit → Undo takes a choice back");
  auto* segTfEdit = new QPushButton("Edit…");
  segTfEdit->setObjectName("segmentTfEdit");
  segTfEdit->setToolTip(
      "Shape the chosen segment's own transfer function in the editor (from the volume's when "
      "it has none); each edit is an undo step of the editor");
  auto* segTfRow = new QHBoxLayout;
  segTfRow->addWidget(segTf_, 1);
  segTfRow->addWidget(segTfEdit);
  form3d->addRow("TF…", segTfRow);
  connect(segTfEdit, &QPushButton::clicked, this, [this] {
    if (const uint8_t label = currentLabel()) emit editTfRequested(label);
  });
  layout->addWidget(view3d);

  // Statistics.
  auto* statsBox = new QGroupBox("Statistics");
  auto* statsLayout = new QVBoxLayout(statsBox);
  stats_ = new QTableWidget(0, 9);
  stats_->setObjectName("segmentStats");
  stats_->setHorizontalHeaderLabels(
      {"Segment", "Voxels", "Volume mL", "Mean", "SD", "Min", "Max", "Median", "SUVpeak"});
  stats_->horizontalHeaderItem(8)->setToolTip(
      "The highest mean SUVbw in a 1 cm³ sphere inside the segment (PERCIST): of a PET with "
      "its SUV attributes, or of the fused PET overlay");
  stats_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  stats_->verticalHeader()->hide();
  stats_->setMinimumHeight(90);
  stats_->setToolTip(
      "Each segment's voxels, volume and the values inside it, counted again after each edit");
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
  connect(sendSeg_, &QPushButton::clicked, this, [this] { sendSegDialog(); });
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
  connect(fromTf, &QPushButton::clicked, this, [this] {
    if (m_.document.empty()) return;
    const Volume& v = *m_.document.volume();
    const ValueRange stored = storedRange(v);
    const double a = v.toPhysical(stored.min), b = v.toPhysical(stored.max);
    try {
      const HuRange r =
          rangeFromTransferFunction(m_.render.params(), {std::min(a, b), std::max(a, b)});
      setTools([r](SegmentToolSettings& s) { s.range = r; });
    } catch (const std::exception& e) {
      fail("Cannot take the range from the transfer function", e.what());
    }
  });
  connect(scissorsKeep_, &QCheckBox::toggled, this,
          [this](bool on) { setTools([on](SegmentToolSettings& s) { s.scissorsKeep = on; }); });
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
  connect(segTf_, &QComboBox::currentIndexChanged, this, [this](int i) {
    const uint8_t label = currentLabel();
    const QString name = segTf_->itemData(i).toString();
    if (!label || refreshing_ || name == "\n") return;
    try {
      std::vector<ControlPoint> points;
      if (!name.isEmpty()) points = findPreset(name.toStdString()).tf.points;
      m_.render.update(kAppearance, [&](RenderParams& p) {
        if (points.empty())
          p.segmentTfs.erase(label);
        else
          p.segmentTfs[label] = points;
      });
    } catch (const std::exception& e) {
      fail("Segment transfer function", e.what());
    }
  });
  connect(blend_, &QSlider::valueChanged, this, [this](int v) {
    if (refreshing_) return;
    m_.render.update(kAppearance, [v](RenderParams& p) { p.segmentBlend = v / 100.0; });
  });
  connect(update, &QPushButton::clicked, this, [this] { updateStatistics(); });
  connect(copy, &QPushButton::clicked, this,
          [this] { QApplication::clipboard()->setText(statisticsText()); });
  connect(csv, &QPushButton::clicked, this, [this] { saveCsv(); });

  // The statistics follow every edit: a burst of them (a paint drag) counts once, 300 ms after
  // the last, on a worker thread.
  statsTimer_ = new QTimer(this);
  statsTimer_->setSingleShot(true);
  statsTimer_->setInterval(300);
  connect(statsTimer_, &QTimer::timeout, this, [this] { refreshStatisticsInBackground(); });
  onModelChange<>(this, m_.segmentation.changed, [this] {
    refreshList();
    statsTimer_->start();
  });
  // An overlay opened or closed: a CT's segments may take their SUVpeak from it now (its
  // window, map and opacity do not change the numbers).
  auto countedOverlay = std::make_shared<const Volume*>(nullptr);
  onModelChange<>(this, m_.fusion.changed, [this, countedOverlay] {
    if (*countedOverlay == m_.fusion.overlay().get()) return;
    *countedOverlay = m_.fusion.overlay().get();
    statsTimer_->start();
  });
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
