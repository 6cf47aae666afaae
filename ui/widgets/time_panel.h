#pragma once
// The time panel of a 4D series (issue 36): a slider over the time points, play/pause, loop
// and the frame rate, driving every view through the document (VolumeDocument::setTimePoint),
// and the time–intensity curve at the crosshair or of the selected ROI, with CSV export.
// Thin: which point to show when is TimePlayer's, the curve's values time_series.h's.
#include <vector>

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include "app_models.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace voxray::ui {

// A small line chart of one value per time point, the point shown marked (QPainter: Qt
// Charts is not a dependency).
class TimeCurveView : public QWidget {
 public:
  explicit TimeCurveView(QWidget* parent = nullptr);
  void setCurve(std::vector<double> values, const QString& title, int current);
  const std::vector<double>& values() const { return values_; }
  QSize sizeHint() const override { return {320, 140}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  std::vector<double> values_;
  QString title_;
  int current_ = 0;
};

class TimePanel : public QWidget {
  Q_OBJECT
 public:
  TimePanel(AppModels& models, QWidget* parent = nullptr);

  QSlider* slider() const { return slider_; }
  QPushButton* playButton() const { return play_; }
  QDoubleSpinBox* fpsBox() const { return fps_; }
  TimeCurveView* curve() const { return curve_; }
  // The curve shown, as CSV (timeIntensityCsv), written to PATH; false with MESSAGE on failure.
  bool exportCsv(const QString& path, QString* message = nullptr) const;

 signals:
  void csvWritten(const QString& path);
  void csvFailed(const QString& message);

 private:
  void refreshSeries();  // another study
  void refreshTime();    // another time point
  void refreshCurve();   // the curve's point or ROI, or the study, changed
  void refreshPlayer();  // play state or rate changed
  void tick();
  void askCsv();
  double nowS() const { return double(clock_.nsecsElapsed()) * 1e-9; }

  AppModels& m_;
  QSlider* slider_;
  QLabel* label_;
  QPushButton* play_;
  QCheckBox* loop_;
  QDoubleSpinBox* fps_;
  TimeCurveView* curve_;
  QPushButton* csv_;
  QTimer timer_;
  QElapsedTimer clock_;
  QString what_, unit_;  // the curve's subject and unit, for the CSV header
};

}  // namespace voxray::ui
