#include "movie_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

#include "quality_choice.h"

namespace voxray::ui {

MovieDialog::MovieDialog(QWidget* window, AppModels& models, MovieController& controller,
                         QString device)
    : QDialog(window), models_(models), controller_(controller), device_(std::move(device)) {
  setWindowTitle("Export movie");
  auto* form = new QFormLayout(this);
  kind_ = new QComboBox;
  kind_->setObjectName("movieKind");
  for (const auto& label : movieKindLabels()) kind_->addItem(QString::fromStdString(label));
  kind_->setToolTip(
      "A 360° orbit of the 3D view from its current camera, or a cine through one slice view's "
      "slices");
  form->addRow("Movie", kind_);
  frames_ = new QSpinBox;
  frames_->setObjectName("movieFrames");
  frames_->setRange(0, 100000);
  frames_->setSpecialValueText("every slice");
  frames_->setToolTip(
      "Orbit: frames over 360° (72 at 24 fps: one turn in 3 s). Cine: slices, spread from the "
      "first to the last");
  form->addRow("Frames", frames_);
  width_ = new QSpinBox;
  height_ = new QSpinBox;
  width_->setObjectName("movieWidth");
  height_->setObjectName("movieHeight");
  for (QSpinBox* s : {width_, height_}) {
    s->setRange(0, 8192);
    s->setSpecialValueText("slice's own");
    s->setToolTip("Frame size in pixels; MP4 rounds an odd size up to even (H.264 4:2:0)");
  }
  form->addRow("Width", width_);
  form->addRow("Height", height_);
  quality_ = new QComboBox;
  quality_->setObjectName("movieQuality");
  for (const QualityChoice& q : qualityChoices()) {
    quality_->addItem(QString::fromStdString(q.label), QString::fromStdString(q.preset));
    quality_->setItemData(quality_->count() - 1, QString::fromStdString(q.tooltip),
                          Qt::ToolTipRole);
  }
  quality_->setCurrentIndex(quality_->findData(QString("reference")));
  form->addRow("Quality", quality_);
  fps_ = new QDoubleSpinBox;
  fps_->setObjectName("movieFps");
  fps_->setRange(1.0, 120.0);
  fps_->setValue(MovieChoice{}.fps);
  fps_->setToolTip("Frames per second of the MP4");
  form->addRow("Frame rate", fps_);
  path_ = new QLineEdit;
  path_->setObjectName("moviePath");
  path_->setPlaceholderText("movie.mp4, or a folder/ for PNG frames");
  auto* row = new QHBoxLayout;
  row->addWidget(path_);
  auto* mp4 = new QPushButton("MP4…");
  auto* folder = new QPushButton("PNG folder…");
  connect(mp4, &QPushButton::clicked, this, [this] { browse(false); });
  connect(folder, &QPushButton::clicked, this, [this] { browse(true); });
  row->addWidget(mp4);
  row->addWidget(folder);
  form->addRow("Save to", row);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
  buttons->addButton("Export", QDialogButtonBox::AcceptRole);
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    if (exportTo(path_->text())) accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
  connect(kind_, &QComboBox::currentIndexChanged, this, &MovieDialog::kindChanged);
  kindChanged();
}

void MovieDialog::kindChanged() {
  // Each kind starts from its own defaults: 72 frames at 1024 x 768, or every slice at the
  // slice's own size.
  const bool cine = kind_->currentIndex() >= 2;
  const MovieChoice defaults;
  frames_->setValue(cine ? 0 : defaults.frames);
  width_->setValue(cine ? 0 : defaults.size.x);
  height_->setValue(cine ? 0 : defaults.size.y);
  quality_->setEnabled(!cine);  // a cine samples the slice views' planes, not the raycaster
}

MovieChoice MovieDialog::choice() const {
  MovieChoice c;
  c.kind = kind_->currentIndex();
  c.frames = frames_->value();
  c.size = {width_->value(), height_->value()};
  c.quality = quality_->currentData().toString().toStdString();
  c.fps = fps_->value();
  return c;
}

void MovieDialog::browse(bool folder) {
  QSettings s;
  const QString start = s.value("lastMovieFolder").toString();
  QString path =
      folder ? QFileDialog::getExistingDirectory(this, "Folder for PNG frames", start)
             : QFileDialog::getSaveFileName(this, "Export movie", start, "MP4 movie (*.mp4)",
                                            nullptr, QFileDialog::DontConfirmOverwrite);
  if (path.isEmpty()) return;
  s.setValue("lastMovieFolder", folder ? path : QFileInfo(path).absolutePath());
  if (folder) path += "/";
  if (!folder && QFileInfo(path).suffix().isEmpty()) path += ".mp4";
  path_->setText(path);
}

bool MovieDialog::fail(const QString& message) {
  if (error_)
    error_(message);
  else
    QMessageBox::warning(this, "Cannot export the movie", message);
  return false;
}

bool MovieDialog::exportTo(const QString& path) {
  auto volume = models_.document.volume();
  if (!volume) return fail("Open a volume first.");
  if (controller_.busy()) return fail("A movie is being exported; wait for it or cancel it.");
  if (path.isEmpty()) return fail("Choose where to save the movie.");
  const MovieChoice c = choice();
  MoviePlan plan;
  std::vector<std::string> existing;
  try {
    plan = planMovie(c, models_.render, models_.windowLevel.value(), *volume, path.toStdString());
    if (!plan.cine && (c.size.x <= 0 || c.size.y <= 0 || c.frames <= 0))
      return fail("An orbit needs a width, a height and at least one frame.");
    existing = existingMovieFiles(path.toStdString(), movieFrameCount(plan, *volume));
  } catch (const std::exception& e) {
    return fail(QString::fromStdString(e.what()));
  }
  if (!existing.empty()) {
    const int count = int(existing.size());
    const bool replace =
        confirm_ ? confirm_(existing.front(), count)
                 : QMessageBox::question(
                       this, "Replace files?",
                       QString("%1 already exists%2. Replace %3?")
                           .arg(QString::fromStdString(existing.front()))
                           .arg(count > 1
                                    ? QString(" (and %1 more of the movie's frames)").arg(count - 1)
                                    : QString())
                           .arg(count > 1 ? "them" : "it"),
                       QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
    if (!replace) return false;
  }
  MovieSettings settings;
  settings.fps = c.fps;
  controller_.start(volume, device_.toStdString(), plan, path, settings);
  return true;
}

}  // namespace voxray::ui
