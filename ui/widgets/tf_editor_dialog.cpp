#include "tf_editor_dialog.h"

#include <chrono>

#include <QColorDialog>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QMessageBox>
#include <QShortcut>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "coupling.h"
#include "gui_post.h"
#include "voxray/io/error.h"

namespace voxray::ui {

namespace {

QDoubleSpinBox* huSpin(const char* name) {
  auto* s = new QDoubleSpinBox;
  s->setObjectName(name);
  s->setRange(-32768.0, 32767.0);
  s->setDecimals(1);
  s->setSingleStep(10.0);
  s->setKeyboardTracking(false);
  return s;
}

}  // namespace

TfEditorDialog::TfEditorDialog(AppModels& models, RenderScheduler* scheduler, QWidget* parent)
    : QDialog(parent),
      models_(models),
      model_(std::make_unique<TfEditorModel>(models.render)),
      histogramTask_(postTo(this)),
      tf2dTask_(postTo(this)) {
  setObjectName("tfEditor");
  setWindowTitle("Transfer function");
  setModal(false);

  curve_ = new TfCurveView(*model_, this);
  curveType_ = new QComboBox;
  curveType_->setObjectName("tfCurveType");
  curveType_->addItems({"Straight lines", "Smooth (monotone cubic)"});
  curveType_->setToolTip("Between points: straight lines, or a smooth curve that never overshoots");
  unit_ = new QDoubleSpinBox;
  unit_->setObjectName("tfUnit");
  unit_->setRange(0.0, 100.0);
  unit_->setDecimals(2);
  unit_->setSuffix(" mm");
  unit_->setSpecialValueText("one voxel");
  unit_->setKeyboardTracking(false);
  unit_->setToolTip(
      "The ray length an opacity is stated for (3D Slicer's scalar opacity unit distance); "
      "'one voxel' = the smallest voxel spacing, as Voxray's presets");
  auto* logScale = new QCheckBox("Log histogram");
  logScale->setObjectName("tfLogHistogram");
  logScale->setChecked(true);
  auto* top = new QComboBox;
  top->setObjectName("tfOpacityTop");
  for (double t : {1.0, 0.5, 0.2, 0.1, 0.05}) top->addItem(QString::number(t), t);
  top->setToolTip("The opacity at the top of the curve: smaller to shape small opacities");

  huLo_ = huSpin("tfHuLo");
  huHi_ = huSpin("tfHuHi");
  auto* fitVisibleButton = new QPushButton("Fit to visible");
  fitVisibleButton->setObjectName("tfFitVisible");
  fitVisibleButton->setToolTip(
      "Show the HU range that holds the volume's voxels (bins of the histogram with at least "
      "0.1 % of them), without the few outliers that squeeze the rest");
  auto* fitCurveButton = new QPushButton("Fit to curve");
  fitCurveButton->setObjectName("tfFitCurve");
  fitCurveButton->setToolTip("Show the HU range where the opacity is above 0");
  auto* fitVolumeButton = new QPushButton("Reset");
  fitVolumeButton->setObjectName("tfFitVolume");
  fitVolumeButton->setToolTip("Show the volume's whole HU range");

  pointHu_ = huSpin("tfPointHu");
  pointOpacity_ = new QDoubleSpinBox;
  pointOpacity_->setObjectName("tfPointOpacity");
  pointOpacity_->setRange(0.0, 1.0);
  pointOpacity_->setDecimals(4);
  pointOpacity_->setSingleStep(0.01);
  pointOpacity_->setKeyboardTracking(false);
  pointColor_ = new QPushButton("Colour…");
  pointColor_->setObjectName("tfPointColor");

  auto* load = new QPushButton("Load…");
  load->setObjectName("tfLoad");
  load->setToolTip(
      "Voxray transfer function (.json), 3D Slicer volume property (.vp) or one preset of a "
      "Slicer preset list (presets.xml)");
  auto* save = new QPushButton("Save…");
  save->setObjectName("tfSave");
  undo_ = new QPushButton("Undo");
  undo_->setObjectName("tfUndo");
  redo_ = new QPushButton("Redo");
  redo_->setObjectName("tfRedo");
  status_ = new QLabel;
  status_->setObjectName("tfStatus");
  status_->setWordWrap(true);

  auto* options = new QHBoxLayout;
  options->addWidget(new QLabel("Curve"));
  options->addWidget(curveType_);
  options->addWidget(new QLabel("Opacity per"));
  options->addWidget(unit_);
  options->addWidget(logScale);
  options->addWidget(new QLabel("Top"));
  options->addWidget(top);
  options->addStretch();
  auto* axis = new QHBoxLayout;
  axis->addWidget(new QLabel("HU from"));
  axis->addWidget(huLo_);
  axis->addWidget(new QLabel("to"));
  axis->addWidget(huHi_);
  axis->addWidget(fitVisibleButton);
  axis->addWidget(fitCurveButton);
  axis->addWidget(fitVolumeButton);
  axis->addStretch();
  auto* point = new QHBoxLayout;
  point->addWidget(new QLabel("Point: HU"));
  point->addWidget(pointHu_);
  point->addWidget(new QLabel("opacity"));
  point->addWidget(pointOpacity_);
  point->addWidget(pointColor_);
  point->addStretch();
  auto* buttons = new QHBoxLayout;
  for (QPushButton* b : {load, save, undo_, redo_}) buttons->addWidget(b);
  buttons->addStretch();
  auto* oneD = new QWidget;
  auto* oneDLayout = new QVBoxLayout(oneD);
  oneDLayout->addLayout(options);
  oneDLayout->addWidget(curve_, 1);
  oneDLayout->addLayout(axis);
  oneDLayout->addLayout(point);
  tabs_ = new QTabWidget;
  tabs_->setObjectName("tfTabs");
  tabs_->addTab(oneD, "1D");
  tabs_->addTab(make2dTab(), "2D");
  tabs_->setTabToolTip(1,
                       "Opacity over HU and gradient magnitude: boundaries without the "
                       "tissue of the same HU");
  tabs_->addTab(makePresetsTab(scheduler), "Presets");
  tabs_->setTabToolTip(2, "Every dvr preset on the open volume: click one to use it");
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(tabs_, 1);
  layout->addLayout(buttons);
  layout->addWidget(status_);
  resize(640, 460);

  auto refresh = [this] {
    QSignalBlocker b1(curveType_), b2(unit_);
    curveType_->setCurrentIndex(model_->property().curve == TfCurve::Smooth ? 1 : 0);
    unit_->setValue(model_->property().unitDistanceMm);
    undo_->setEnabled(model_->canUndo());
    redo_->setEnabled(model_->canRedo());
    showSelection();
    show2dSelection();
  };
  modelLinks_ = new QObject(this);
  onModelChange<>(modelLinks_, model_->changed, refresh);
  curve_->selectionChanged = [this] { showSelection(); };
  connect(curveType_, &QComboBox::currentIndexChanged, this,
          [this](int i) { model_->setCurve(i == 1 ? TfCurve::Smooth : TfCurve::Linear); });
  connect(unit_, &QDoubleSpinBox::valueChanged, this,
          [this](double mm) { model_->setUnitDistance(mm); });
  connect(logScale, &QCheckBox::toggled, curve_, &TfCurveView::setLogHistogram);
  connect(top, &QComboBox::currentIndexChanged, this,
          [this, top](int) { curve_->setOpacityTop(top->currentData().toDouble()); });
  auto axisChanged = [this] { curve_->setHuRange(huLo_->value(), huHi_->value()); };
  connect(huLo_, &QDoubleSpinBox::valueChanged, this, axisChanged);
  connect(huHi_, &QDoubleSpinBox::valueChanged, this, axisChanged);
  connect(fitVisibleButton, &QPushButton::clicked, curve_, &TfCurveView::fitVisible);
  connect(fitCurveButton, &QPushButton::clicked, this, [this] { fitCurve(); });
  curve_->rangeChanged = [this] {
    QSignalBlocker b1(huLo_), b2(huHi_);
    huLo_->setValue(curve_->huLo());
    huHi_->setValue(curve_->huHi());
  };
  connect(fitVolumeButton, &QPushButton::clicked, this, [this] { fitVolume(); });
  connect(pointHu_, &QDoubleSpinBox::valueChanged, this, [this](double hu) {
    auto s = curve_->selection();
    if (!s) return;
    if (s->list == TfCurveView::List::Opacity)
      model_->moveOpacityPoint(s->index, hu, model_->property().opacity[s->index].opacity);
    else
      model_->moveColorPoint(s->index, hu);
  });
  connect(pointOpacity_, &QDoubleSpinBox::valueChanged, this, [this](double a) {
    auto s = curve_->selection();
    if (s && s->list == TfCurveView::List::Opacity)
      model_->moveOpacityPoint(s->index, model_->property().opacity[s->index].x, a);
  });
  connect(pointColor_, &QPushButton::clicked, this, [this] {
    auto s = curve_->selection();
    if (!s || s->list != TfCurveView::List::Color) return;
    glm::dvec3 c = model_->property().color[s->index].rgb;
    QColor picked = QColorDialog::getColor(QColor::fromRgbF(float(c.r), float(c.g), float(c.b)),
                                           this, "Colour of the point");
    if (picked.isValid())
      model_->setPointColor(s->index, {picked.redF(), picked.greenF(), picked.blueF()});
  });
  connect(undo_, &QPushButton::clicked, this, [this] { model_->undo(); });
  connect(redo_, &QPushButton::clicked, this, [this] { model_->redo(); });
  connect(load, &QPushButton::clicked, this, [this] {
    QString file = QFileDialog::getOpenFileName(
        this, "Load transfer function", QString(),
        "Transfer functions (*.json *.vp *.xml);;Voxray (*.json);;3D Slicer volume property "
        "(*.vp);;3D Slicer preset list (*.xml)");
    if (file.isEmpty()) return;
    QString error = loadFile(file);
    if (!error.isEmpty()) QMessageBox::warning(this, "Transfer function", error);
  });
  connect(save, &QPushButton::clicked, this, [this] {
    // The file dialog asks before it replaces a file.
    QString file = QFileDialog::getSaveFileName(
        this, "Save transfer function", QString(),
        "Voxray transfer function (*.json);;3D Slicer volume property (*.vp)");
    if (file.isEmpty()) return;
    QString error = saveFile(file);
    if (!error.isEmpty()) QMessageBox::warning(this, "Transfer function", error);
  });
  // Ctrl+Z / Ctrl+Shift+Z in this window: the editor's own history (the main window's Undo
  // is the view's).
  auto* undoKey = new QShortcut(QKeySequence::Undo, this, [this] { model_->undo(); });
  undoKey->setObjectName("tfUndoKey");
  new QShortcut(QKeySequence::Redo, this, [this] { model_->redo(); });
  onModelChange<>(this, models_.document.changed, [this] {
    fitVolume();
    countHistogram();
    if (tabs_->currentIndex() == 1) count2dHistogram();
  });
  connect(tabs_, &QTabWidget::currentChanged, this, [this](int i) {
    if (i == 1) count2dHistogram();
  });
  choosePreset = [this](const QStringList& names) {
    bool ok = false;
    QString name = QInputDialog::getItem(this, "3D Slicer presets", "Preset", names, 0, false, &ok);
    return ok ? name : QString();
  };

  refresh();
  fitVolume();
  countHistogram();
}

TfEditorDialog::~TfEditorDialog() {
  histogramTask_.cancel();
  tf2dTask_.cancel();
  // What listens to the model goes before the model (a member, gone before the children).
  delete curve_;
  delete tf2d_;
  delete gallery_;
  delete modelLinks_;
}

void TfEditorDialog::editTable(uint8_t label) {
  if (label != model_->target()) model_->setTarget(label);  // reopened: the history stays
  QString title = "Transfer function";
  if (label != 0) {
    const Segment* seg = models_.segmentation.segmentation().find(label);
    title = QString("Transfer function of segment %1").arg(label);
    if (seg && !seg->name.empty()) title += " (" + QString::fromStdString(seg->name) + ")";
    tabs_->setCurrentIndex(0);
  }
  setWindowTitle(title);
  tabs_->setTabEnabled(1, label == 0);
  tabs_->setTabEnabled(2, label == 0);
  unit_->setEnabled(label == 0);
}

QString TfEditorDialog::loadFile(const QString& file) {
  try {
    if (file.endsWith(".xml", Qt::CaseInsensitive)) {
      std::vector<VolumeProperty> presets = readSlicerPresetFile(file.toStdString());
      QStringList names;
      for (const VolumeProperty& p : presets) names << QString::fromStdString(p.name);
      QString name = choosePreset(names);
      if (name.isEmpty()) return {};
      model_->setProperty(findProperty(presets, name.toStdString(), file.toStdString()));
    } else {
      model_->setProperty(readVolumePropertyFile(file.toStdString()));
    }
    if (hasGradientOpacity(model_->property()))
      status_->setText(
          "This transfer function has a gradient-magnitude opacity: dvr fades flat regions and "
          "keeps boundaries (not in shadows, ambient occlusion or cinematic). The curve above "
          "is the scalar opacity.");
    return {};
  } catch (const Error& e) {
    return QString::fromStdString(e.what());
  }
}

QString TfEditorDialog::saveFile(const QString& file) {
  try {
    writeVolumePropertyFile(model_->property(), file.toStdString());
    return {};
  } catch (const Error& e) {
    return QString::fromStdString(e.what());
  }
}

void TfEditorDialog::countHistogram() {
  histogramReady_ = false;
  std::shared_ptr<const Volume> v = models_.document.volume();
  if (!v) {
    curve_->setHistogram({}, 1.0, 0.0);
    status_->setText("No volume open.");
    return;
  }
  status_->setText("Counting the histogram…");
  histogramTask_.cancel();
  histogramTask_.wait();
  histogramTask_.start([this, v] {
    auto start = std::chrono::steady_clock::now();
    StoredHistogram h = storedHistogram(*v, histogramTask_.cancelFlag());
    double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (h.empty()) return;  // cancelled: a newer count follows
    histogramTask_.post([this, h = std::move(h), v, ms]() mutable {
      if (models_.document.volume() != v) return;  // another volume meanwhile
      uint64_t total = h.total;
      curve_->setHistogram(std::move(h), v->slope, v->intercept);
      status_->setText(
          QString("Histogram of %1 voxels (%2 ms).").arg(qulonglong(total)).arg(ms, 0, 'f', 0));
      histogramReady_ = true;
    });
  });
}

void TfEditorDialog::showSelection() {
  auto s = curve_->selection();
  QSignalBlocker b1(pointHu_), b2(pointOpacity_);
  pointHu_->setEnabled(bool(s));
  pointOpacity_->setEnabled(s && s->list == TfCurveView::List::Opacity);
  pointColor_->setEnabled(s && s->list == TfCurveView::List::Color);
  if (!s) return;
  const VolumeProperty& vp = model_->property();
  if (s->list == TfCurveView::List::Opacity) {
    pointHu_->setValue(vp.opacity[s->index].x);
    pointOpacity_->setValue(vp.opacity[s->index].opacity);
  } else {
    pointHu_->setValue(vp.color[s->index].hu);
  }
}

void TfEditorDialog::fitCurve() {
  const VolumeProperty& vp = model_->property();
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (size_t i = 0; i < vp.opacity.size(); ++i) {
    // A point counts when the curve is above 0 next to it.
    bool visible = vp.opacity[i].opacity > 0.0 || (i > 0 && vp.opacity[i - 1].opacity > 0.0) ||
                   (i + 1 < vp.opacity.size() && vp.opacity[i + 1].opacity > 0.0);
    if (!visible) continue;
    lo = any ? std::min(lo, vp.opacity[i].x) : vp.opacity[i].x;
    hi = any ? std::max(hi, vp.opacity[i].x) : vp.opacity[i].x;
    any = true;
  }
  if (!any || !(hi > lo)) return;
  double pad = 0.1 * (hi - lo);
  huLo_->setValue(lo - pad);
  huHi_->setValue(hi + pad);
}

void TfEditorDialog::fitVolume() {
  double lo = -1024.0, hi = 3071.0;
  if (auto v = models_.document.volume()) {
    ValueRange r = storedRange(*v);
    lo = std::min(v->toPhysical(r.min), v->toPhysical(r.max));
    hi = std::max(v->toPhysical(r.min), v->toPhysical(r.max));
    if (!(hi > lo)) hi = lo + 1.0;
  }
  curve_->setFullRange(lo, hi);
  curve_->resetRange();
  curve_->rangeChanged();  // the fields, also when the range was already this
}

}  // namespace voxray::ui
