// Clip box, light and slice display controls, and the panel that stacks all groups.
#include <array>
#include <iterator>
#include <utility>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include "clip_box_math.h"
#include "control_panel.h"
#include "coupling.h"
#include "gui_post.h"
#include "light_gizmo.h"
#include "lighting_meter.h"
#include "spec_widgets.h"
#include "value_look.h"
#include "voxray/engine/quality.h"

namespace voxray::ui {

namespace {

// GROUP under a header that folds it away, so that the panel fits a 1080-line screen with
// the groups not in use folded. The whole box hides: rows the group itself shows or hides
// (by mode) keep their own state.
QWidget* foldable(QGroupBox* group, bool open) {
  auto* section = new QWidget;
  auto* layout = new QVBoxLayout(section);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  auto* header = new QToolButton;
  header->setObjectName("fold" + group->objectName());
  header->setText(group->title());
  header->setToolTip(QString("Show or hide the %1 controls").arg(group->title()));
  header->setCheckable(true);
  header->setChecked(open);
  header->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  header->setAutoRaise(true);
  header->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  group->setTitle("");
  auto show = [header, group](bool on) {
    header->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
    group->setVisible(on);
  };
  show(open);
  QObject::connect(header, &QToolButton::toggled, group, show);
  layout->addWidget(header);
  layout->addWidget(group);
  return section;
}

// The measurement's owner: lives and dies with the Light group (its results are posted to
// the group, so none arrives after it).
class MeterHolder : public QObject {
 public:
  MeterHolder(QObject* parent, AppModels& models)
      : QObject(parent), meter(models.document, models.lighting, postTo(parent)) {}
  LightingMeter meter;
};

// Each model's cost and error on this scene beside the Model combo, and the button that
// measures them on the view on screen.
void addLightingFigures(QFormLayout* form, QGroupBox* box, AppModels& models) {
  RenderStateModel& m = models.render;
  auto* figures = new QLabel;
  figures->setObjectName("lightingFigures");
  figures->setWordWrap(true);
  auto* measure = new QPushButton("Measure on this view");
  measure->setObjectName("measureLighting");
  measure->setToolTip(
      "Renders this view with each lighting model at 256\u00d7192 and compares it with the "
      "Monte Carlo reference (cinematic: with its own image at 256 samples); in the "
      "background, about 3 minutes on 2 busy CPU cores (the sample CT)");
  auto* holder = new MeterHolder(box, models);
  auto refresh = [figures, measure, holder, &models] {
    std::string text = models.lighting.text(models.render.params().lighting);
    if (!holder->meter.lastError().empty())
      text += "\nMeasurement failed: " + holder->meter.lastError();
    figures->setText(QString::fromStdString(text));
    figures->setToolTip(QString::fromStdString(models.lighting.tooltip()));
    // Mip and unshaded frames are not lit: there is nothing to measure.
    const RenderParams& p = models.render.params();
    measure->setEnabled(!models.document.empty() && !models.lighting.measuring() &&
                        p.mode != Mode::Mip && p.shading);
  };
  refresh();
  onModelChange<>(figures, models.lighting.changed, refresh);
  onModelChange<>(figures, models.document.changed, refresh);
  onModelChange<unsigned>(figures, m.changed, [refresh](unsigned what) {
    if (what & kAppearance) refresh();
  });
  QObject::connect(measure, &QPushButton::clicked, box, [holder, &models] {
    if (models.document.empty()) return;
    const glm::ivec2 size{256, 192};
    RenderParams view = settledFrame(models.render.params(), models.render.quality().preset, size,
                                     size, models.document.minSpacingMm());
    holder->meter.measure(view, models.device);
  });
  form->addRow(figures);
  form->addRow(measure);
}

}  // namespace

QGroupBox* makeClipGroup(AppModels& models) {
  RenderStateModel& m = models.render;
  auto* box = new QGroupBox("Clip box (% of extent)");
  auto* grid = new QGridLayout(box);
  const ParamSpec& clip = findRenderParamSpec("clip");
  grid->addWidget(new QLabel("from"), 0, 1);
  grid->addWidget(new QLabel("to"), 0, 2);
  // Each row names the patient directions its index axis runs between in this volume.
  std::array<QLabel*, 3> axisLabels{};
  for (int a = 0; a < 3; ++a) {
    axisLabels[size_t(a)] = new QLabel;
    axisLabels[size_t(a)]->setObjectName(QString("clipAxis%1").arg(a));
    grid->addWidget(axisLabels[size_t(a)], a + 1, 0);
  }
  auto refreshAxes = [axisLabels, &models] {
    const char* index[] = {"i", "j", "k"};
    auto names = clipAxisLabels(models.document.empty() ? glm::dmat3(1.0)
                                                        : models.document.volume()->direction);
    for (size_t a = 0; a < 3; ++a) {
      axisLabels[a]->setText(QString::fromStdString(names[a]));
      axisLabels[a]->setToolTip(
          QString("Index axis %1, from the box's low face to its high face").arg(index[a]));
    }
  };
  for (int a = 0; a < 3; ++a) {
    for (int hi = 0; hi < 2; ++hi) {
      auto* s = makeSpin(clip, 100.0);  // fractions shown as percent
      s->setSuffix(" %");
      s->setToolTip(hi ? "Where the box ends along this axis, in % of the volume's extent"
                       : "Where the box starts along this axis, in % of the volume's extent");
      bindSpin(
          s, m, kClip,
          [a, hi](const RenderParams& p) { return 100.0 * (hi ? p.clip.hi[a] : p.clip.lo[a]); },
          [a, hi](RenderParams& p, double v) {
            // The same clamping as a handle drag: the box never turns inside out.
            double f = v / 100.0;
            if (hi)
              p.clip.hi[a] = std::max(f, p.clip.lo[a] + 0.02);
            else
              p.clip.lo[a] = std::min(f, p.clip.hi[a] - 0.02);
          });
      grid->addWidget(s, a + 1, hi + 1);
    }
  }
  auto* reset = new QPushButton("Reset box");
  reset->setToolTip("Back to the whole volume");
  QObject::connect(reset, &QPushButton::clicked, reset,
                   [&m] { m.update(kClip, [](RenderParams& p) { p.clip = ClipBox{}; }); });
  QCheckBox* handles = makeOverlayCheck(
      models.render, &ViewOverlays::clipHandles, "Handles in 3D view", "showClipHandles",
      "Show the box's edges and face handles (drag a handle to move a face)");
  grid->addWidget(reset, 4, 0, 1, 3);
  grid->addWidget(handles, 5, 0, 1, 3);
  refreshAxes();
  onModelChange<>(box, models.document.changed, refreshAxes);
  return box;
}

QGroupBox* makeLightGroup(AppModels& models) {
  RenderStateModel& m = models.render;
  auto* box = new QGroupBox("Light");
  auto* form = new QFormLayout(box);
  // The lighting model (phong, shadows, ao, cinematic) sits with the light it shapes; the
  // Rendering group has no room left on a 1080-line screen.
  form->addRow("Model", makeParamCombo(m, kAppearance, "lighting"));
  addLightingFigures(form, box, models);
  auto* follow = new QCheckBox("Follows the camera");
  follow->setObjectName("lightFollowsCamera");
  follow->setToolTip("On: the light turns with the camera. Off: it stays fixed to the patient");
  auto refreshFollow = [follow, &m] {
    QSignalBlocker b(follow);
    follow->setChecked(m.params().light.followCamera);
  };
  refreshFollow();
  onModelChange<unsigned>(follow, m.changed, [refreshFollow](unsigned what) {
    if (what & kLight) refreshFollow();
  });
  QObject::connect(follow, &QCheckBox::toggled, follow, [&models](bool on) {
    // Switching frames keeps the light where it is now; only later camera moves differ.
    RenderStateModel& m = models.render;
    if (models.document.empty()) {
      m.update(kLight, [on](RenderParams& p) { p.light.followCamera = on; });
      return;
    }
    LightParams l = withFollowCamera(*models.document.volume(), m.params(), on);
    l.followCamera = on;
    m.update(kLight, [&](RenderParams& p) { p.light = l; });
  });
  form->addRow(follow);
  // The position's unit and axes depend on the frame: they change with the check box.
  std::array<QDoubleSpinBox*, 3> position{};
  std::array<QLabel*, 3> positionNames{};
  for (int a = 0; a < 3; ++a) {
    auto* s = makeSpin(findRenderParamSpec("light"));
    s->setObjectName(QString("lightPosition%1").arg(a));
    bindSpin(
        s, m, kLight, [a](const RenderParams& p) { return p.light.position[a]; },
        [a](RenderParams& p, double v) { p.light.position[a] = v; });
    position[size_t(a)] = s;
    positionNames[size_t(a)] = new QLabel;
    form->addRow(positionNames[size_t(a)], s);
  }
  auto refreshUnit = [position, positionNames, &m] {
    LightPositionUnit u = lightPositionUnit(m.params().light.followCamera);
    for (size_t a = 0; a < 3; ++a) {
      positionNames[a]->setText(QString::fromStdString("Position " + u.axes[a]));
      position[a]->setSuffix(QString::fromStdString(u.suffix));
      position[a]->setToolTip(QString::fromStdString(u.tooltip));
    }
  };
  refreshUnit();
  onModelChange<unsigned>(box, m.changed, [refreshUnit](unsigned what) {
    if (what & kLight) refreshUnit();
  });
  struct Term {
    const char* name;
    const char* key;  // its render parameter: the range comes from the spec
    double LightParams::*field;
  };
  const Term terms[] = {{"Ambient", "ambient", &LightParams::ambient},
                        {"Diffuse", "diffuse", &LightParams::diffuse},
                        {"Specular", "specular", &LightParams::specular},
                        {"Shininess", "shininess", &LightParams::shininess}};
  for (const Term& t : terms) {
    auto* s = makeSpin(findRenderParamSpec(t.key));
    auto field = t.field;
    bindSpin(
        s, m, kLight, [field](const RenderParams& p) { return p.light.*field; },
        [field](RenderParams& p, double v) { p.light.*field = v; });
    form->addRow(t.name, s);
  }
  form->addRow(
      makeOverlayCheck(m, &ViewOverlays::lightHandle, "Light handle in 3D view", "showLightHandle",
                       "Show the light as a sun in the 3D view (drag it to move the light)"));
  return box;
}

QGroupBox* makeSliceGroup(WindowLevelModel& wl, RenderStateModel& state, VolumeDocument& doc) {
  auto* box = new QGroupBox("Slices");
  auto* form = new QFormLayout(box);
  auto* preset = new QComboBox;
  preset->setObjectName("windowLevelPreset");
  preset->setToolTip("Window/level of the slice views (CT presets: width/level in HU)");
  preset->addItem("(custom)");
  for (const auto& p : windowLevelPresets())
    preset->addItem(
        QString("%1 (%2/%3)").arg(QString::fromStdString(p.name)).arg(p.wl.width).arg(p.wl.level));
  auto* width = makeSpin("windowWidth", windowLevelDomain().width);
  auto* level = makeSpin("windowLevel", windowLevelDomain().level);
  width->setToolTip("Window width of the slice views (right drag in a slice: left-right)");
  level->setToolTip("Window level (centre) of the slice views (right drag in a slice: up-down)");
  auto* source = new QLabel;
  source->setObjectName("windowLevelSource");
  source->setWordWrap(true);
  auto refresh = [preset, width, level, source, &wl, &doc] {
    QSignalBlocker b1(preset), b2(width), b3(level);
    // The volume's unit (value_look.h): HU only for values that are HU.
    const QString unit = " " + QString::fromStdString(doc.empty() ? std::string("HU")
                                                                  : valueUnitLabel(*doc.volume()));
    width->setSuffix(unit);
    level->setSuffix(unit);
    width->setValue(wl.value().width);
    level->setValue(wl.value().level);
    source->setText(QString::fromStdString(wl.source()));
    int index = 0;
    const auto& all = windowLevelPresets();
    for (size_t i = 0; i < all.size(); ++i)
      if (all[i].wl.width == wl.value().width && all[i].wl.level == wl.value().level)
        index = int(i) + 1;
    preset->setCurrentIndex(index);
  };
  refresh();
  onModelChange<>(box, wl.changed, refresh);
  onModelChange<>(box, doc.changed, refresh);
  QObject::connect(preset, &QComboBox::currentIndexChanged, box, [&wl](int i) {
    if (i > 0) wl.applyPreset(windowLevelPresets()[size_t(i - 1)].name);
  });
  QObject::connect(width, &QDoubleSpinBox::valueChanged, box, [&wl](double w) {
    wl.set({w, wl.value().level});
  });
  QObject::connect(level, &QDoubleSpinBox::valueChanged, box, [&wl](double l) {
    wl.set({wl.value().width, l});
  });
  form->addRow("W/L preset", preset);
  form->addRow("Window", width);
  form->addRow("Level", level);
  form->addRow(source);
  auto* smooth = new QCheckBox("Interpolate (trilinear)");
  smooth->setObjectName("sliceInterp");
  smooth->setToolTip("Off: each voxel is shown as a block (nearest neighbour)");
  auto refreshSmooth = [smooth, &state] {
    QSignalBlocker b(smooth);
    smooth->setChecked(state.sliceInterp() == Interp::Linear);
  };
  refreshSmooth();
  onModelChange<unsigned>(box, state.changed, [refreshSmooth](unsigned what) {
    if (what & kSlices) refreshSmooth();
  });
  QObject::connect(smooth, &QCheckBox::toggled, box, [&state](bool on) {
    state.setSliceInterp(on ? Interp::Linear : Interp::Nearest);
  });
  form->addRow(smooth);
  return box;
}

QScrollArea* makeControlPanel(AppModels& models) {
  auto* column = new QWidget;
  auto* layout = new QVBoxLayout(column);
  // Folded at start: the light (set once and left) and the standard views (the mouse and R
  // do the same), so that the rest fits 1920x1080 unscrolled.
  const std::pair<QGroupBox*, bool> groups[] = {
      {makeRenderGroup(models.render, models.document), true},
      {makeQualityGroup(models.render), true},
      {makeCameraGroup(models.render), false},
      {makeSliceGroup(models.windowLevel, models.render, models.document), true},
      {makeClipGroup(models), true},
      {makeLightGroup(models), false},
      {makeMprGroup(models.crosshair, models.render), false}};
  const char* names[] = {"Rendering", "Quality", "Camera", "Slices", "Clip", "Light", "Mpr"};
  for (size_t i = 0; i < std::size(groups); ++i) {
    groups[i].first->setObjectName(QString(names[i]) + "Group");
    layout->addWidget(foldable(groups[i].first, groups[i].second));
  }
  layout->addStretch();
  auto* scroll = new QScrollArea;
  scroll->setObjectName("controlPanel");
  scroll->setWidget(column);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(column->sizeHint().width() + 20);
  return scroll;
}

}  // namespace voxray::ui
