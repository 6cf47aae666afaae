#include "time_panel.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include "coupling.h"
#include "measurement_model.h"
#include "time_series.h"

namespace voxray::ui {

TimeCurveView::TimeCurveView(QWidget* parent) : QWidget(parent) {
  setObjectName("timeCurve");
  setMinimumHeight(110);
  setMaximumHeight(160);  // a glance beside the views, not a panel that takes their room
  setToolTip("The value over the time points; the point shown is marked");
}

void TimeCurveView::setCurve(std::vector<double> values, const QString& title, int current) {
  values_ = std::move(values);
  title_ = title;
  current_ = current;
  update();
}

void TimeCurveView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), palette().base());
  p.setPen(palette().text().color());
  const QRect plot = rect().adjusted(48, 20, -10, -18);
  p.drawText(rect().adjusted(4, 2, -4, 0), Qt::AlignTop | Qt::AlignLeft, title_);
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values_)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (values_.size() < 2 || !std::isfinite(lo) || plot.width() < 10 || plot.height() < 10) return;
  if (hi - lo < 1e-9) lo -= 1.0, hi += 1.0;  // a flat curve in the middle
  auto at = [&](size_t t, double v) {
    return QPointF(plot.left() + plot.width() * double(t) / double(values_.size() - 1),
                   plot.bottom() - plot.height() * (v - lo) / (hi - lo));
  };
  p.setPen(palette().mid().color());
  p.drawRect(plot);
  p.setPen(palette().text().color());
  p.drawText(QRect(0, plot.top() - 7, 44, 14), Qt::AlignRight | Qt::AlignVCenter,
             QString::number(hi, 'g', 4));
  p.drawText(QRect(0, plot.bottom() - 7, 44, 14), Qt::AlignRight | Qt::AlignVCenter,
             QString::number(lo, 'g', 4));
  p.drawText(QRect(plot.left(), plot.bottom() + 2, plot.width(), 14), Qt::AlignCenter,
             QString("time point 0 … %1").arg(values_.size() - 1));
  QPen line(palette().highlight().color(), 2);
  p.setPen(line);
  for (size_t t = 1; t < values_.size(); ++t)
    if (std::isfinite(values_[t - 1]) && std::isfinite(values_[t]))
      p.drawLine(at(t - 1, values_[t - 1]), at(t, values_[t]));
  if (current_ >= 0 && size_t(current_) < values_.size() && std::isfinite(values_[current_])) {
    p.setBrush(palette().highlight());
    p.drawEllipse(at(size_t(current_), values_[size_t(current_)]), 4, 4);
  }
}

TimePanel::TimePanel(AppModels& models, QWidget* parent) : QWidget(parent), m_(models) {
  setObjectName("timePanel");
  clock_.start();
  auto* layout = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  play_ = new QPushButton("Play");
  play_->setObjectName("timePlay");
  play_->setCheckable(true);
  play_->setToolTip("Play the time points at the frame rate in every view, the 3D view included");
  slider_ = new QSlider(Qt::Horizontal);
  slider_->setObjectName("timeSlider");
  slider_->setToolTip("The time point (phase) every view shows");
  slider_->setPageStep(1);
  label_ = new QLabel;
  label_->setObjectName("timeLabel");
  label_->setMinimumWidth(90);
  loop_ = new QCheckBox("Loop");
  loop_->setObjectName("timeLoop");
  loop_->setToolTip("Start again at the first time point after the last (off: stop there)");
  fps_ = new QDoubleSpinBox;
  fps_->setObjectName("timeFps");
  fps_->setRange(TimePlayer::kMinFps, TimePlayer::kMaxFps);
  fps_->setDecimals(1);
  fps_->setSuffix(" fps");
  fps_->setToolTip("Time points shown per second while playing");
  row->addWidget(play_);
  row->addWidget(slider_, 1);
  row->addWidget(label_);
  row->addWidget(loop_);
  row->addWidget(fps_);
  layout->addLayout(row);
  curve_ = new TimeCurveView;
  layout->addWidget(curve_, 1);
  csv_ = new QPushButton("Export curve as CSV…");
  csv_->setObjectName("timeCsv");
  csv_->setToolTip("Save the time–intensity curve: one line per time point");
  layout->addWidget(csv_, 0, Qt::AlignRight);

  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, &TimePanel::tick);
  connect(slider_, &QSlider::valueChanged, this, [this](int t) {
    m_.document.setTimePoint(t);
    if (m_.player.playing()) m_.player.play(t, nowS());  // playing on from the point chosen
  });
  connect(play_, &QPushButton::toggled, this, [this](bool on) {
    if (on)
      m_.player.play(m_.document.timePoint(), nowS());
    else
      m_.player.pause();
  });
  connect(loop_, &QCheckBox::toggled, this, [this](bool on) { m_.player.setLoop(on); });
  connect(fps_, &QDoubleSpinBox::valueChanged, this,
          [this](double fps) { m_.player.setFps(fps, m_.document.timePoint(), nowS()); });
  connect(csv_, &QPushButton::clicked, this, &TimePanel::askCsv);
  onModelChange<>(this, m_.document.changed, [this] { refreshSeries(); });
  onModelChange<>(this, m_.document.timeChanged, [this] { refreshTime(); });
  onModelChange<>(this, m_.player.changed, [this] { refreshPlayer(); });
  onModelChange<>(this, m_.crosshair.changed, [this] { refreshCurve(); });
  onModelChange<>(this, m_.measurements.changed, [this] { refreshCurve(); });
  refreshPlayer();
  refreshSeries();
}

void TimePanel::refreshSeries() {
  const int n = m_.document.timePoints();
  {
    QSignalBlocker block(slider_);
    slider_->setRange(0, std::max(0, n - 1));
    slider_->setValue(m_.document.timePoint());
  }
  setEnabled(n > 1);
  if (n <= 1) m_.player.pause();
  refreshTime();
}

void TimePanel::refreshTime() {
  {
    QSignalBlocker block(slider_);
    slider_->setValue(m_.document.timePoint());
  }
  label_->setText(
      m_.document.timePoints() > 1
          ? QString("time %1 / %2").arg(m_.document.timePoint() + 1).arg(m_.document.timePoints())
          : QString("one time point"));
  refreshCurve();
}

void TimePanel::refreshCurve() {
  if (m_.document.timePoints() <= 1) {
    curve_->setCurve({}, "A 4D series plots its time–intensity curve here", 0);
    csv_->setEnabled(false);
    return;
  }
  const Volume& v = *m_.document.volume();
  unit_ = QString::fromStdString(readoutUnit(v));
  const Measurement* roi = m_.measurements.find(m_.measurements.selected());
  std::vector<double> values;
  if (roi && (roi->kind == MeasureKind::Ellipse || roi->kind == MeasureKind::Rect) &&
      roi->points.size() == 2) {
    values = timeIntensityInRoi(m_.document.series(), *roi);
    what_ = QString("ROI %1 mean").arg(roi->id);
  } else {
    const glm::ivec3 c = m_.crosshair.voxel();
    values = timeIntensityAtVoxel(m_.document.series(), glm::dvec3(c));
    what_ = QString("crosshair [%1, %2, %3]").arg(c.x).arg(c.y).arg(c.z);
  }
  curve_->setCurve(std::move(values), what_ + " (" + unit_ + ")", m_.document.timePoint());
  csv_->setEnabled(true);
}

void TimePanel::refreshPlayer() {
  {
    QSignalBlocker b1(play_), b2(loop_), b3(fps_);
    play_->setChecked(m_.player.playing());
    play_->setText(m_.player.playing() ? "Pause" : "Play");
    loop_->setChecked(m_.player.loop());
    fps_->setValue(m_.player.fps());
  }
  if (m_.player.playing()) {
    // Two ticks a frame: a tick late by up to half a frame still shows the right point.
    timer_.start(std::max(1, int(500.0 / m_.player.fps())));
  } else {
    timer_.stop();
  }
}

void TimePanel::tick() {
  m_.document.setTimePoint(m_.player.tick(nowS(), m_.document.timePoints()));
}

bool TimePanel::exportCsv(const QString& path, QString* message) const {
  const std::string text =
      timeIntensityCsv(curve_->values(), what_.toStdString(), unit_.toStdString());
  std::ofstream out(path.toStdString(), std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (out) return true;
  if (message) *message = path + ": cannot write the file (check the folder and free space)";
  return false;
}

void TimePanel::askCsv() {
  const QString path = QFileDialog::getSaveFileName(this, "Export time–intensity curve",
                                                    "time_intensity.csv", "CSV (*.csv)");
  if (path.isEmpty()) return;
  QString message;
  if (exportCsv(path, &message))
    emit csvWritten(path);
  else
    emit csvFailed(message);
}

}  // namespace voxray::ui
