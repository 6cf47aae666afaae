#include "tf_editor_dialog.h"

#include <chrono>

#include <QColorDialog>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QMessageBox>
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

TfEditorDialog::TfEditorDialog(AppModels& models, QWidget* parent)
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
  fitVisibleButton->setToolTip("Show the HU range where the opacity is above 0");
  auto* fitVolumeButton = new QPushButton("Whole volume");
  fitVolumeButton->setObjectName("tfFitVolume");

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
  connect(fitVisibleButton, &QPushButton::clicked, this, [this] { fitVisible(); });
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
  onModelChange<>(this, models_.document.changed, [this] {
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
  delete modelLinks_;
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

void TfEditorDialog::fitVisible() {
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
  QSignalBlocker b1(huLo_), b2(huHi_);
  huLo_->setValue(lo);
  huHi_->setValue(hi);
  curve_->setHuRange(lo, hi);
}

}  // namespace voxray::ui

namespace voxray::ui {

QWidget* TfEditorDialog::make2dTab() {
  auto* tab = new QWidget;
  tf2d_ = new Tf2dView(*model_, tab);
  auto spin = [](const char* name, double lo, double hi, int decimals, double step) {
    auto* s = new QDoubleSpinBox;
    s->setObjectName(name);
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setSingleStep(step);
    s->setKeyboardTracking(false);
    return s;
  };
  tf2dHu0_ = spin("tf2dHu0", -32768.0, 32767.0, 1, 10.0);
  tf2dHu1_ = spin("tf2dHu1", -32768.0, 32767.0, 1, 10.0);
  tf2dG0_ = spin("tf2dG0", 0.0, 1e6, 1, 1.0);
  tf2dG1_ = spin("tf2dG1", 0.0, 1e6, 1, 1.0);
  tf2dOpacity_ = spin("tf2dOpacity", 0.0, 1.0, 3, 0.05);
  tf2dSoft_ = spin("tf2dSoft", 0.0, 1.0, 2, 0.05);
  tf2dSoft_->setToolTip("The soft edge: the outer part of the shape where the opacity falls to 0");
  tf2dHu0_->setToolTip("The selected shape's HU range (a triangle: its width at the top)");
  tf2dHu1_->setToolTip(tf2dHu0_->toolTip());
  tf2dG0_->setToolTip(
      "The selected shape's gradient-magnitude range in HU/mm (a triangle's apex stays at 0)");
  tf2dG1_->setToolTip(tf2dG0_->toolTip());
  tf2dOpacity_->setToolTip("The shape's peak opacity, per voxel as the 1D curve's");
  tf2dColor_ = new QPushButton("Colour…");
  tf2dColor_->setObjectName("tf2dColorButton");
  tf2dColor_->setToolTip("The selected shape's colour");
  tf2dStatus_ = new QLabel;
  tf2dStatus_->setObjectName("tf2dStatus");
  tf2dStatus_->setWordWrap(true);

  auto* extent = new QHBoxLayout;
  extent->addWidget(new QLabel("HU"));
  extent->addWidget(tf2dHu0_);
  extent->addWidget(new QLabel("to"));
  extent->addWidget(tf2dHu1_);
  extent->addWidget(new QLabel("|∇| HU/mm"));
  extent->addWidget(tf2dG0_);
  extent->addWidget(new QLabel("to"));
  extent->addWidget(tf2dG1_);
  extent->addStretch();
  auto* look = new QHBoxLayout;
  look->addWidget(new QLabel("Opacity"));
  look->addWidget(tf2dOpacity_);
  look->addWidget(new QLabel("Soft edge"));
  look->addWidget(tf2dSoft_);
  look->addWidget(tf2dColor_);
  look->addStretch();
  auto* layout = new QVBoxLayout(tab);
  layout->addWidget(tf2d_, 1);
  layout->addLayout(extent);
  layout->addLayout(look);
  layout->addWidget(tf2dStatus_);

  tf2d_->selectionChanged = [this] { show2dSelection(); };
  auto extentTyped = [this] {
    if (auto i = tf2d_->selection())
      model_->setTf2dExtent(*i, tf2dHu0_->value(), tf2dHu1_->value(), tf2dG0_->value(),
                            tf2dG1_->value());
  };
  for (QDoubleSpinBox* s : {tf2dHu0_, tf2dHu1_, tf2dG0_, tf2dG1_})
    connect(s, &QDoubleSpinBox::valueChanged, this, extentTyped);
  connect(tf2dOpacity_, &QDoubleSpinBox::valueChanged, this, [this](double a) {
    if (auto i = tf2d_->selection()) model_->setTf2dOpacity(*i, a);
  });
  connect(tf2dSoft_, &QDoubleSpinBox::valueChanged, this, [this](double soft) {
    if (auto i = tf2d_->selection()) model_->setTf2dSoft(*i, soft);
  });
  connect(tf2dColor_, &QPushButton::clicked, this, [this] {
    if (auto i = tf2d_->selection()) tf2d_->pickColor(*i);
  });
  show2dSelection();
  return tab;
}

void TfEditorDialog::show2dSelection() {
  auto i = tf2d_->selection();
  const auto& ps = model_->property().tf2d.primitives;
  if (i && *i >= ps.size()) i.reset();
  QSignalBlocker b1(tf2dHu0_), b2(tf2dHu1_), b3(tf2dG0_), b4(tf2dG1_), b5(tf2dOpacity_),
      b6(tf2dSoft_);
  for (QWidget* w : std::initializer_list<QWidget*>{tf2dHu0_, tf2dHu1_, tf2dG0_, tf2dG1_,
                                                    tf2dOpacity_, tf2dSoft_, tf2dColor_})
    w->setEnabled(bool(i));
  if (!i) return;
  const Tf2dPrimitive& p = ps[*i];
  tf2dHu0_->setValue(p.hu0);
  tf2dHu1_->setValue(p.hu1);
  tf2dG0_->setValue(p.g0);
  tf2dG1_->setValue(p.g1);
  tf2dOpacity_->setValue(p.opacity);
  tf2dSoft_->setValue(p.soft);
}

void TfEditorDialog::count2dHistogram() {
  std::shared_ptr<const Volume> v = models_.document.volume();
  if (v && tf2dCounted_.lock() == v) return;  // counted, or being counted
  tf2dReady_ = false;
  tf2dCounted_ = v;
  tf2dTask_.cancel();
  tf2dTask_.wait();
  if (!v) {
    tf2d_->setHistogram({});
    tf2dStatus_->setText("No volume open.");
    return;
  }
  tf2dStatus_->setText("Counting the value × gradient histogram…");
  tf2dTask_.start([this, v] {
    auto start = std::chrono::steady_clock::now();
    Tf2dHistogram h = tf2dHistogram(*v, 0.0, tf2dTask_.cancelFlag());
    double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (h.empty()) return;  // cancelled: a newer count follows
    tf2dTask_.post([this, h = std::move(h), v, ms] {
      if (models_.document.volume() != v) return;  // another volume meanwhile
      tf2d_->setHistogram(h);
      tf2dStatus_->setText(QString("2D histogram of %1 voxels, |∇| up to %2 HU/mm (%3 ms). "
                                   "Shapes replace the 1D curve in dvr.")
                               .arg(qulonglong(h.total))
                               .arg(h.gradientMax, 0, 'f', 0)
                               .arg(ms, 0, 'f', 0));
      tf2dReady_ = true;
    });
  });
}

}  // namespace voxray::ui
