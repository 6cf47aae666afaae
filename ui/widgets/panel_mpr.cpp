// The side panel's MPR group: the planes' outlines in the 3D view, each slice view's slab
// (thickness and mode) and the reset of turned planes. The planes themselves turn in the
// slice views (round handles on the crosshair lines).
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

#include "control_panel.h"
#include "coupling.h"

namespace voxray::ui {

namespace {

constexpr double kMaxSlabMm = 200.0;
const char* kModeNames[] = {"MIP", "MinIP", "Mean"};  // SlabMode's order

QWidget* slabRow(CrosshairModel& crosshair, Orientation o, QWidget* owner) {
  const QString name = QString(toString(o));
  auto* thickness = new QDoubleSpinBox;
  thickness->setObjectName("slab_" + name);
  thickness->setRange(0.0, kMaxSlabMm);
  thickness->setSingleStep(1.0);
  thickness->setDecimals(1);
  thickness->setSuffix(" mm");
  thickness->setSpecialValueText("thin");
  thickness->setKeyboardTracking(false);
  thickness->setToolTip("Slab thickness of the " + name +
                        " view in mm, centred on its plane (thin: one plane)");
  auto* mode = new QComboBox;
  mode->setObjectName("slabMode_" + name);
  for (const char* m : kModeNames) mode->addItem(m);
  mode->setToolTip(
      "How the slab's samples combine: brightest (MIP, vessels and bone), darkest (MinIP, "
      "airways) or their mean (a thick slice, less noise)");
  auto refresh = [thickness, mode, &crosshair, o] {
    QSignalBlocker a(thickness), b(mode);
    thickness->setValue(crosshair.slab(o).thicknessMm);
    mode->setCurrentIndex(int(crosshair.slab(o).mode));
  };
  refresh();
  onModelChange<>(owner, crosshair.changed, refresh);
  auto apply = [thickness, mode, &crosshair, o] {
    crosshair.setSlab(o, {thickness->value(), SlabMode(mode->currentIndex())});
  };
  QObject::connect(thickness, &QDoubleSpinBox::valueChanged, owner, apply);
  QObject::connect(mode, &QComboBox::currentIndexChanged, owner, apply);
  auto* row = new QWidget;
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(thickness, 1);
  layout->addWidget(mode);
  return row;
}

}  // namespace

QCheckBox* makeOverlayCheck(RenderStateModel& m, bool ViewOverlays::*field, const QString& text,
                            const QString& name, const QString& tooltip) {
  auto* check = new QCheckBox(text);
  check->setObjectName(name);
  check->setToolTip(tooltip);
  auto refresh = [check, &m, field] {
    QSignalBlocker b(check);
    check->setChecked(m.overlays().*field);
  };
  refresh();
  onModelChange<unsigned>(check, m.changed, [refresh](unsigned what) {
    if (what & kSlices) refresh();
  });
  QObject::connect(check, &QCheckBox::toggled, check, [&m, field](bool on) {
    ViewOverlays o = m.overlays();
    o.*field = on;
    m.setOverlays(o);
  });
  return check;
}

QGroupBox* makeMprGroup(CrosshairModel& crosshair, RenderStateModel& state) {
  auto* box = new QGroupBox("Planes: oblique and slabs");
  auto* form = new QFormLayout(box);
  form->addRow(makeOverlayCheck(
      state, &ViewOverlays::planes, "Show planes in 3D view", "showPlanes",
      "Outline the three slice planes in the 3D view, in the slice views' colours"));
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal}) {
    QString label = QString(toString(o)) + " slab";
    label[0] = label[0].toUpper();
    form->addRow(label, slabRow(crosshair, o, box));
  }
  auto* reset = new QPushButton("Reset planes");
  reset->setObjectName("resetPlanes");
  reset->setToolTip(
      "Turn the three slice planes back to the acquisition planes (Ctrl+Shift+R). Drag a "
      "round handle on a slice view's crosshair line to turn them.");
  auto refresh = [reset, &crosshair] { reset->setEnabled(crosshair.rotated()); };
  refresh();
  onModelChange<>(box, crosshair.changed, refresh);
  QObject::connect(reset, &QPushButton::clicked, box, [&crosshair] { crosshair.resetRotation(); });
  form->addRow(reset);
  return box;
}

}  // namespace voxray::ui
