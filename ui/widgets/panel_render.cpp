// Render mode, transfer-function preset and its shift, iso range, gradient, interpolation,
// quality and camera controls.
#include <cmath>

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include "camera_control.h"
#include "control_panel.h"
#include "coupling.h"
#include "voxray/engine/transfer_function.h"

namespace voxray::ui {

namespace {

QDoubleSpinBox* huSpin() {
  auto* s = new QDoubleSpinBox;
  s->setRange(-3000, 32767);
  s->setDecimals(0);
  s->setSingleStep(10);
  s->setSuffix(" HU");
  s->setKeyboardTracking(false);
  return s;
}

// The seed's shift slider: moves the preset's transfer function along HU, e.g. to show
// bone at a lower density. Clicking the value sets it back to 0.
QWidget* makePresetShiftRow(RenderStateModel& m) {
  auto* row = new QWidget;
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* slider = new QSlider(Qt::Horizontal);
  slider->setObjectName("presetShift");
  slider->setRange(int(-kPresetShiftLimitHu), int(kPresetShiftLimitHu));
  slider->setSingleStep(10);
  slider->setPageStep(100);
  slider->setToolTip("Move the preset's transfer function along HU");
  auto* value = new QPushButton;
  value->setObjectName("presetShiftReset");
  value->setFlat(true);
  value->setToolTip("Back to 0");
  value->setFixedWidth(value->fontMetrics().horizontalAdvance("+1000 HU") + 12);
  auto refresh = [slider, value, &m] {
    QSignalBlocker block(slider);
    slider->setValue(int(std::lround(m.params().presetShiftHu)));
    value->setText(QString::asprintf("%+d HU", slider->value()));
  };
  refresh();
  onModelChange<unsigned>(slider, m.changed, [refresh](unsigned what) {
    if (what & kAppearance) refresh();
  });
  QObject::connect(slider, &QSlider::valueChanged, slider, [&m](int hu) { m.setPresetShift(hu); });
  QObject::connect(value, &QPushButton::clicked, value, [&m] { m.setPresetShift(0.0); });
  layout->addWidget(slider, 1);
  layout->addWidget(value);
  return row;
}

}  // namespace

QGroupBox* makeRenderGroup(RenderStateModel& m) {
  auto* box = new QGroupBox("Rendering");
  auto* form = new QFormLayout(box);

  auto* mode = new QComboBox;
  mode->addItems({"Iso surface", "Volume (DVR)", "MIP"});
  bindCombo(
      mode, m, kAppearance, [](const RenderParams& p) { return double(int(p.mode)); },
      [](RenderParams& p, double v) { p.mode = Mode(int(v)); });
  form->addRow("Mode", mode);

  auto* preset = new QComboBox;
  preset->addItem("(mode default)");
  for (const auto& p : builtinPresets()) preset->addItem(QString::fromStdString(p.name));
  auto refreshPreset = [preset, &m] {
    QSignalBlocker block(preset);
    int i = preset->findText(QString::fromStdString(m.params().preset), Qt::MatchFixedString);
    preset->setCurrentIndex(std::max(i, 0));
  };
  refreshPreset();
  onModelChange<unsigned>(preset, m.changed, [refreshPreset](unsigned what) {
    if (what & kAppearance) refreshPreset();
  });
  QObject::connect(preset, &QComboBox::currentIndexChanged, preset, [preset, &m](int i) {
    if (i == 0) {
      m.update(kAppearance, [](RenderParams& p) { p.preset.clear(); });
      return;
    }
    try {
      m.applyPreset(preset->currentText().toStdString());
    } catch (const std::exception& e) {
      QMessageBox::warning(preset, "Preset", e.what());
    }
  });
  form->addRow("Preset", preset);
  form->addRow("Shift", makePresetShiftRow(m));

  auto* isoLo = huSpin();
  bindSpin(
      isoLo, m, kAppearance, [](const RenderParams& p) { return p.isoLo; },
      [](RenderParams& p, double v) { p.isoLo = v; });
  auto* isoHi = huSpin();
  bindSpin(
      isoHi, m, kAppearance, [](const RenderParams& p) { return p.isoHi; },
      [](RenderParams& p, double v) { p.isoHi = v; });
  form->addRow("Iso from", isoLo);
  form->addRow("Iso to", isoHi);

  auto* gradient = new QComboBox;
  gradient->addItems({"Central difference", "Sobel", "Zucker-Hummel"});
  bindCombo(
      gradient, m, kAppearance, [](const RenderParams& p) { return double(int(p.gradient)); },
      [](RenderParams& p, double v) { p.gradient = Gradient(int(v)); });
  form->addRow("Gradient", gradient);

  auto* interp = new QComboBox;
  interp->addItems({"Nearest", "Trilinear"});
  bindCombo(
      interp, m, kAppearance, [](const RenderParams& p) { return double(int(p.interp)); },
      [](RenderParams& p, double v) { p.interp = Interp(int(v)); });
  form->addRow("Interpolation", interp);
  return box;
}

QGroupBox* makeQualityGroup(RenderStateModel& m) {
  auto* box = new QGroupBox("Quality");
  auto* form = new QFormLayout(box);
  static const QList<QSize> sizes = {{0, 0}, {512, 384}, {640, 480}, {800, 600}, {1024, 768}};
  auto* resolution = new QComboBox;
  resolution->addItems({"Window size", "512 × 384", "640 × 480", "800 × 600", "1024 × 768"});
  static const QList<double> steps = {2.0, 1.0, 0.5};
  auto* step = new QComboBox;
  step->addItems({"Fast (2× step)", "Normal", "Fine (½ step)"});
  auto refresh = [resolution, step, &m] {
    QSignalBlocker b1(resolution), b2(step);
    QSize s(m.quality().resolution.x, m.quality().resolution.y);
    resolution->setCurrentIndex(std::max(0, int(sizes.indexOf(s))));
    step->setCurrentIndex(std::max(0, int(steps.indexOf(m.quality().stepScale))));
  };
  refresh();
  onModelChange<unsigned>(box, m.changed, [refresh](unsigned what) {
    if (what & kQuality) refresh();
  });
  QObject::connect(resolution, &QComboBox::currentIndexChanged, box, [&m](int i) {
    Quality q = m.quality();
    q.resolution = {sizes[i].width(), sizes[i].height()};
    m.setQuality(q);
  });
  QObject::connect(step, &QComboBox::currentIndexChanged, box, [&m](int i) {
    Quality q = m.quality();
    q.stepScale = steps[i];
    m.setQuality(q);
  });
  form->addRow("Resolution", resolution);
  form->addRow("Step", step);
  return box;
}

QGroupBox* makeCameraGroup(RenderStateModel& m) {
  auto* box = new QGroupBox("Camera");
  auto* grid = new QGridLayout(box);
  const StandardView views[] = {StandardView::Anterior, StandardView::Posterior,
                                StandardView::Left,     StandardView::Right,
                                StandardView::Superior, StandardView::Inferior};
  int i = 0;
  for (StandardView v : views) {
    auto* b = new QPushButton(toString(v));
    QObject::connect(b, &QPushButton::clicked, b, [&m, v] {
      m.update(kCamera, [v](RenderParams& p) { setStandardView(p.camera, v); });
    });
    grid->addWidget(b, i / 3, i % 3);
    ++i;
  }
  auto* reset = new QPushButton("Reset view");
  QObject::connect(reset, &QPushButton::clicked, reset,
                   [&m] { m.update(kCamera, [](RenderParams& p) { resetCamera(p.camera); }); });
  grid->addWidget(reset, 2, 0, 1, 3);
  return box;
}

}  // namespace voxray::ui
