#include "fusion_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include "coupling.h"
#include "load_controller.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/volume_file.h"

namespace voxray::ui {

FusionPanel::FusionPanel(FusionModel& fusion, QWidget* parent) : QWidget(parent), fusion_(fusion) {
  setObjectName("fusionPanel");
  auto* layout = new QVBoxLayout(this);
  name_ = new QLabel("No overlay");
  name_->setObjectName("fusionName");
  name_->setWordWrap(true);
  auto* open = new QPushButton("Open overlay volume…");
  open->setObjectName("fusionOpen");
  open->setToolTip(
      "A second volume (PET, MR, a prior) drawn over this one through its own geometry");
  connect(open, &QPushButton::clicked, this, &FusionPanel::openRequested);
  auto* remove = new QPushButton("Remove overlay");
  remove->setObjectName("fusionRemove");
  connect(remove, &QPushButton::clicked, this, [this] { fusion_.clear(); });
  on_ = new QCheckBox("Show overlay");
  on_->setObjectName("fusionOn");
  map_ = new QComboBox;
  map_->setObjectName("fusionColormap");
  for (const std::string& m : fusionColormaps()) map_->addItem(QString::fromStdString(m));
  lo_ = new QDoubleSpinBox;
  hi_ = new QDoubleSpinBox;
  lo_->setObjectName("fusionLo");
  hi_->setObjectName("fusionHi");
  for (QDoubleSpinBox* b : {lo_, hi_}) {
    b->setRange(-1e7, 1e7);
    b->setDecimals(3);
    b->setKeyboardTracking(false);
  }
  lo_->setToolTip("Below this value the overlay is transparent (the overlay's unit; SUV for PET)");
  hi_->setToolTip("The colour map's end (the overlay's unit; SUV for PET)");
  opacity_ = new QSlider(Qt::Horizontal);
  opacity_->setObjectName("fusionOpacity");
  opacity_->setRange(0, 100);
  opacity_->setToolTip("Opacity of the overlay over the slices (and its peak opacity in 3D)");
  time_ = new QSpinBox;
  time_->setObjectName("fusionTime");
  time_->setKeyboardTracking(false);
  time_->setToolTip(
      "A 4D overlay's time point. With as many time points as the study it follows the study's "
      "time slider (the same index); otherwise it shows the one chosen here");
  error_ = new QLabel;
  error_->setObjectName("fusionError");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #d04040");
  auto* form = new QFormLayout;
  form->addRow(on_);
  form->addRow("Colour map", map_);
  form->addRow("Window low", lo_);
  form->addRow("Window high", hi_);
  form->addRow("Opacity", opacity_);
  form->addRow("Time point", time_);
  layout->addWidget(name_);
  layout->addWidget(open);
  layout->addWidget(remove);
  layout->addLayout(form);
  layout->addWidget(error_);
  layout->addStretch(1);
  connect(on_, &QCheckBox::toggled, this, &FusionPanel::apply);
  connect(map_, &QComboBox::currentIndexChanged, this, &FusionPanel::apply);
  connect(lo_, &QDoubleSpinBox::valueChanged, this, &FusionPanel::apply);
  connect(hi_, &QDoubleSpinBox::valueChanged, this, &FusionPanel::apply);
  connect(opacity_, &QSlider::valueChanged, this, &FusionPanel::apply);
  connect(time_, &QSpinBox::valueChanged, this, [this](int t) { fusion_.setOwnTimePoint(t); });
  onModelChange<>(this, fusion_.changed, [this] { showModel(); });
  showModel();
}

void FusionPanel::showModel() {
  const bool any = bool(fusion_.overlay());
  for (QWidget* w : std::initializer_list<QWidget*>{on_, map_, lo_, hi_, opacity_})
    w->setEnabled(any);
  const FusionSettings& s = fusion_.settings();
  const QSignalBlocker b1(on_), b2(map_), b3(lo_), b4(hi_), b5(opacity_), b6(time_);
  const TimeFollow& t = fusion_.time();
  time_->setRange(0, t.count() - 1);
  time_->setValue(t.shown());
  time_->setSuffix(t.follows()     ? QString(" (follows the study)")
                   : t.count() > 1 ? QString(" of 0-%1").arg(t.count() - 1)
                                   : QString());
  time_->setEnabled(any && t.count() > 1 && !t.follows());
  QString unit;
  if (any) {
    unit = " " + QString::fromStdString(fusionUnit(*fusion_.overlay()));
    QString text = QString::fromStdString(fusion_.name());
    for (const std::string& w : fusion_.warnings()) text += "\n⚠ " + QString::fromStdString(w);
    name_->setText(text);
  } else {
    name_->setText("No overlay");
  }
  lo_->setSuffix(unit);
  hi_->setSuffix(unit);
  on_->setChecked(s.on);
  map_->setCurrentText(QString::fromStdString(s.colormap));
  lo_->setValue(s.lo);
  hi_->setValue(s.hi);
  opacity_->setValue(int(std::lround(s.opacity * 100.0)));
  error_->clear();
}

void FusionPanel::apply() {
  FusionSettings s = fusion_.settings();
  s.on = on_->isChecked();
  s.colormap = map_->currentText().toStdString();
  s.lo = lo_->value();
  s.hi = hi_->value();
  s.opacity = opacity_->value() / 100.0;
  try {
    fusion_.setSettings(s);
    error_->clear();
  } catch (const std::exception& e) {
    error_->setText(QString::fromStdString(e.what()).replace("--overlay-window", "Window"));
  }
}

OverlayLoader::OverlayLoader(AppModels& models, QWidget* dialogParent)
    : QObject(dialogParent), models_(models), loader_(new LoadController(dialogParent)) {
  loader_->setParent(this);
  connect(loader_, &LoadController::loaded, this,
          [this](VolumeSeries series, const QString& name, const QString&) {
            if (series.empty()) return;
            // A 4D overlay: every time point, shown by the rule of time_follow.h.
            models_.fusion.setMainTime(models_.document.timePoint(), models_.document.timePoints());
            models_.fusion.setOverlaySeries(std::move(series), name.toStdString(),
                                            models_.document.volume().get());
            models_.fusion.setSource(sourcePath_, sourceFlags_);
            QStringList warnings;
            for (const std::string& w : models_.fusion.warnings())
              warnings << QString::fromStdString(w);
            emit opened(name, warnings);
          });
  connect(loader_, &LoadController::failed, this, &OverlayLoader::failed);
}

void OverlayLoader::load(const std::string& input, const LoadOptions& options) {
  // Where it comes from, for a session (one overlay loads at a time: the loader's own rule).
  sourcePath_ = QFileInfo(QString::fromStdString(input)).absoluteFilePath().toStdString();
  sourceFlags_ = flagsFromLoadOptions(options);
  loader_->load(input, options, QFileInfo(QString::fromStdString(input)).fileName());
}

std::string askVolumeInput(QWidget* parent, const QString& title) {
  QSettings s;
  QStringList patterns;
  for (const auto& e : volumeFileExtensions()) patterns << "*" + QString::fromStdString(e);
  const QString file = QFileDialog::getOpenFileName(
      parent, title, s.value("lastFolder", QDir::homePath()).toString(),
      "Volume files (" + patterns.join(' ') + ");;Any file of a DICOM series (*)");
  if (file.isEmpty()) return {};
  const QFileInfo info(file);
  s.setValue("lastFolder", info.absolutePath());
  for (const QString& p : patterns)
    if (file.endsWith(p.mid(1), Qt::CaseInsensitive)) return file.toStdString();
  return info.absolutePath().toStdString();  // a DICOM file: its series' folder
}

}  // namespace voxray::ui
