// Render mode, transfer-function preset and its shift, iso range, gradient, interpolation,
// quality and camera controls.
#include <cmath>

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include "camera_control.h"
#include "control_panel.h"
#include "coupling.h"
#include "quality_choice.h"
#include "render_controls.h"
#include "spec_widgets.h"
#include "value_look.h"
#include "voxray/engine/transfer_function.h"

namespace voxray::ui {

namespace {

// The unit of the open volume's values (valueUnit): HU before any volume, as the presets.
QString unitOf(const VolumeDocument& doc) {
  return QString::fromStdString(doc.empty() ? std::string("HU") : valueUnitLabel(*doc.volume()));
}

// The seed's shift slider: moves the preset's transfer function along HU, e.g. to show
// bone at a lower density. Clicking the value sets it back to 0.
QWidget* makePresetShiftRow(RenderStateModel& m, VolumeDocument& doc) {
  auto* row = new QWidget;
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* slider = new QSlider(Qt::Horizontal);
  slider->setObjectName("presetShift");
  slider->setRange(int(-kPresetShiftLimitHu), int(kPresetShiftLimitHu));
  slider->setSingleStep(10);
  slider->setPageStep(100);
  slider->setToolTip("Move the preset's transfer function along the values (HU for a CT)");
  auto* value = new QPushButton;
  value->setObjectName("presetShiftReset");
  value->setFlat(true);
  value->setToolTip("Back to 0");
  value->setFixedWidth(value->fontMetrics().horizontalAdvance("+1000 value") + 12);
  auto refresh = [slider, value, &m, &doc] {
    QSignalBlocker block(slider);
    slider->setValue(int(std::lround(m.params().presetShiftHu)));
    value->setText(QString::asprintf("%+d ", slider->value()) + unitOf(doc));
  };
  refresh();
  onModelChange<unsigned>(slider, m.changed, [refresh](unsigned what) {
    if (what & kAppearance) refresh();
  });
  onModelChange<>(slider, doc.changed, refresh);
  QObject::connect(slider, &QSlider::valueChanged, slider, [&m](int hu) { m.setPresetShift(hu); });
  QObject::connect(value, &QPushButton::clicked, value, [&m] { m.setPresetShift(0.0); });
  layout->addWidget(slider, 1);
  layout->addWidget(value);
  return row;
}

// A spin box with the range of render parameter KEY, named NAME, bound to one FIELD of it.
QDoubleSpinBox* fieldSpin(RenderStateModel& m, const char* key, const char* name,
                          double RenderParams::*field) {
  auto* spin = makeSpin(findRenderParamSpec(key));
  spin->setObjectName(name);
  bindSpin(
      spin, m, kAppearance, [field](const RenderParams& p) { return p.*field; },
      [field](RenderParams& p, double v) { p.*field = v; });
  return spin;
}

}  // namespace

QGroupBox* makeRenderGroup(RenderStateModel& m, VolumeDocument& doc) {
  auto* box = new QGroupBox("Rendering");
  auto* form = new QFormLayout(box);

  form->addRow("Mode", makeParamCombo(m, kAppearance, "mode"));
  // What lighting cinematic renders when the mode says otherwise (renderControlsFor).
  auto* note = new QLabel;
  note->setObjectName("renderNote");
  note->setWordWrap(true);
  form->addRow(note);

  // Only the presets made for the current mode: a dvr table named in MIP would be a label
  // for something not rendered. The preset's name is each item's data.
  auto* preset = new QComboBox;
  preset->setObjectName("preset");
  preset->setToolTip(
      "Transfer-function preset: which HU ranges show, in which colours (presets are made for "
      "CT)");
  auto refreshPreset = [preset, &m] {
    QSignalBlocker block(preset);
    preset->clear();
    preset->addItem("(mode default)", QString());
    const std::string& current = m.params().preset;
    for (const auto& p : builtinPresets()) {
      bool fits = presetFitsMode(p.name, m.params().mode);
      // The command line may pair a preset with another mode (--preset CT-Bone --mode
      // iso colours the surface by CT-Bone): then it is listed, saying so.
      if (!fits && p.name != current) continue;
      preset->addItem(QString::fromStdString(fits ? p.name : p.name + " (" + p.mode + " preset)"),
                      QString::fromStdString(p.name));
      preset->setItemData(preset->count() - 1, QString::fromStdString(p.description),
                          Qt::ToolTipRole);
    }
    int i = preset->findData(QString::fromStdString(current));
    preset->setCurrentIndex(std::max(i, 0));
  };
  refreshPreset();
  onModelChange<unsigned>(preset, m.changed, [refreshPreset](unsigned what) {
    if (what & kAppearance) refreshPreset();
  });
  QObject::connect(preset, &QComboBox::currentIndexChanged, preset, [preset, &m](int i) {
    if (i <= 0) {
      m.update(kAppearance, [](RenderParams& p) { p.preset.clear(); });
      return;
    }
    try {
      m.applyPreset(preset->currentData().toString().toStdString());
    } catch (const std::exception& e) {
      QMessageBox::warning(preset, "Preset", e.what());
    }
  });
  form->addRow("Preset", preset);
  form->addRow("Shift", makePresetShiftRow(m, doc));

  auto* isoLo = fieldSpin(m, "iso", "isoLo", &RenderParams::isoLo);
  auto* isoHi = fieldSpin(m, "iso", "isoHi", &RenderParams::isoHi);
  form->addRow("Iso from", isoLo);
  form->addRow("Iso to", isoHi);
  // MIP's grey window (the --window parameter); width 0 = the volume's whole range.
  auto* mipWidth = fieldSpin(m, "window", "mipWindow", &RenderParams::windowWidth);
  mipWidth->setMinimum(0.0);
  mipWidth->setSpecialValueText("whole range");
  auto* mipLevel = fieldSpin(m, "window", "mipLevel", &RenderParams::windowLevel);
  form->addRow("MIP window", mipWidth);
  form->addRow("MIP level", mipLevel);
  // The specs say HU (the CT presets'); an MR or an unscaled raw volume has its own unit.
  auto showUnit = [isoLo, isoHi, mipWidth, mipLevel, &doc] {
    for (QDoubleSpinBox* spin : {isoLo, isoHi, mipWidth, mipLevel})
      spin->setSuffix(" " + unitOf(doc));
  };
  showUnit();
  onModelChange<>(box, doc.changed, showUnit);
  auto* gradient = makeParamCombo(m, kAppearance, "gradient");
  form->addRow("Gradient", gradient);
  form->addRow("Interpolation", makeParamCombo(m, kAppearance, "interp"));
  // The iso range means nothing to dvr and mip, the window nothing to iso and dvr, the
  // gradient nothing to mip, and none of them to lighting cinematic (its own dvr): a row
  // shows only where it changes the image, and the note says what cinematic renders.
  auto showModeRows = [form, note, isoLo, isoHi, mipWidth, mipLevel, gradient, &m] {
    const RenderControls c = renderControlsFor(m.params());
    form->setRowVisible(isoLo, c.isoRange);
    form->setRowVisible(isoHi, c.isoRange);
    form->setRowVisible(mipWidth, c.mipWindow);
    form->setRowVisible(mipLevel, c.mipWindow);
    form->setRowVisible(gradient, c.gradient);
    note->setText(QString::fromStdString(c.note));
    form->setRowVisible(note, !c.note.empty());
  };
  showModeRows();
  onModelChange<unsigned>(box, m.changed, [showModeRows](unsigned what) {
    if (what & kAppearance) showModeRows();
  });
  return box;
}

QGroupBox* makeQualityGroup(RenderStateModel& m) {
  auto* box = new QGroupBox("Quality");
  auto* form = new QFormLayout(box);

  // The quality presets with what was measured for each; frames while dragging always use
  // the interactive one.
  static const std::vector<QualityChoice> choices = qualityChoices();
  auto* preset = new QComboBox;
  preset->setObjectName("qualityPreset");
  for (const QualityChoice& c : choices) {
    preset->addItem(QString::fromStdString(c.label));
    preset->setItemData(preset->count() - 1, QString::fromStdString(c.tooltip), Qt::ToolTipRole);
  }
  auto* measured = new QLabel;
  measured->setObjectName("qualityMeasured");
  measured->setWordWrap(true);

  static const QList<QSize> sizes = {{0, 0}, {512, 384}, {640, 480}, {800, 600}, {1024, 768}};
  auto* resolution = new QComboBox;
  resolution->setObjectName("resolution");
  resolution->setToolTip("Image size of the 3D frames (window size: as large as the view)");
  for (QSize s : sizes)
    resolution->addItem(QString::fromStdString(resolutionLabel({s.width(), s.height()})));

  auto refresh = [preset, measured, resolution, &m] {
    QSignalBlocker b1(preset), b2(resolution);
    int i = 0;
    while (i + 1 < int(choices.size()) && choices[size_t(i)].preset != m.quality().preset) ++i;
    preset->setCurrentIndex(i);
    preset->setToolTip(QString::fromStdString(choices[size_t(i)].tooltip));
    // Figures that describe another rendering than this one are not shown as its own.
    std::string mismatch = qualityMismatch(m.quality().preset, m.params());
    measured->setText(
        QString::fromStdString(mismatch.empty() ? choices[size_t(i)].measured : mismatch));
    measured->setToolTip(preset->toolTip());
    // A size from the command line or saved state that the list lacks gets its own entry
    // rather than showing as "Window size".
    glm::ivec2 r = m.quality().resolution;
    while (resolution->count() > sizes.size()) resolution->removeItem(resolution->count() - 1);
    int k = int(sizes.indexOf(QSize(r.x, r.y)));
    if (k < 0) {
      resolution->addItem(QString::fromStdString(resolutionLabel(r)));
      k = resolution->count() - 1;
    }
    resolution->setCurrentIndex(k);
  };
  refresh();
  onModelChange<unsigned>(box, m.changed, [refresh](unsigned what) {
    if (what & (kQuality | kAppearance)) refresh();
  });
  QObject::connect(preset, &QComboBox::currentIndexChanged, box,
                   [&m](int i) { m.setQualityPreset(choices[size_t(i)].preset); });
  QObject::connect(resolution, &QComboBox::currentIndexChanged, box, [&m](int i) {
    if (i >= sizes.size()) return;  // the current size's own entry
    Quality q = m.quality();
    q.resolution = {sizes[i].width(), sizes[i].height()};
    m.setQuality(q);
  });
  // Drag frames shrink (and coarsen) to hold this rate on this machine (AdaptiveQuality).
  auto* dragFps = new QSpinBox;
  dragFps->setObjectName("dragFps");
  dragFps->setRange(int(kDragFpsMin), int(kDragFpsMax));
  dragFps->setSuffix(" fps");
  dragFps->setKeyboardTracking(false);
  dragFps->setToolTip(
      "Frame rate that frames while dragging hold: their size and ray step adapt to the "
      "last frames' render times; the full-quality frame follows when the mouse rests");
  auto refreshFps = [dragFps, &m] {
    QSignalBlocker b(dragFps);
    dragFps->setValue(int(std::lround(m.quality().dragFps)));
  };
  refreshFps();
  onModelChange<unsigned>(dragFps, m.changed, [refreshFps](unsigned what) {
    if (what & kQuality) refreshFps();
  });
  QObject::connect(dragFps, &QSpinBox::valueChanged, box, [&m](int fps) {
    Quality q = m.quality();
    q.dragFps = fps;
    m.setQuality(q);
  });
  // Issue 38: a study larger than this is drawn out of core (RenderWorker::setOutOfCore).
  auto* budget = new QSpinBox;
  budget->setObjectName("gpuBudget");
  budget->setRange(0, kGpuBudgetMibMax);
  budget->setSingleStep(256);
  budget->setSuffix(" MiB");
  budget->setSpecialValueText("automatic");
  budget->setKeyboardTracking(false);
  budget->setToolTip(
      "Device memory the 3D view may hold of a study: a larger study is drawn out of core, "
      "part by part; while dragging it shows the parts on the device at full resolution and "
      "the others coarse, and converges when the mouse rests. Automatic: only a study that "
      "does not fit the device");
  auto refreshBudget = [budget, &m] {
    QSignalBlocker b(budget);
    budget->setValue(m.quality().gpuBudgetMib);
  };
  refreshBudget();
  onModelChange<unsigned>(budget, m.changed, [refreshBudget](unsigned what) {
    if (what & kQuality) refreshBudget();
  });
  QObject::connect(budget, &QSpinBox::valueChanged, box, [&m](int mib) {
    Quality q = m.quality();
    q.gpuBudgetMib = mib;
    m.setQuality(q);
  });
  form->addRow("Preset", preset);
  form->addRow("", measured);
  form->addRow("Resolution", resolution);
  form->addRow("Drag frame rate", dragFps);
  form->addRow("GPU memory budget", budget);
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
    b->setToolTip(
        QString("Look at the patient from the %1 side").arg(QString(toString(v)).toLower()));
    QObject::connect(b, &QPushButton::clicked, b, [&m, v] {
      m.update(kCamera, [v](RenderParams& p) { setStandardView(p.camera, v); });
    });
    grid->addWidget(b, i / 3, i % 3);
    ++i;
  }
  auto* reset = new QPushButton("Reset view");
  reset->setToolTip("Front view of the whole volume (R in the 3D view)");
  QObject::connect(reset, &QPushButton::clicked, reset,
                   [&m] { m.update(kCamera, [](RenderParams& p) { resetCamera(p.camera); }); });
  grid->addWidget(reset, 2, 0, 1, 3);
  return box;
}

}  // namespace voxray::ui
