#pragma once
// Compare (issue 36): today's study (left, the fixed volume: the window's own document,
// crosshair and window/level) beside a prior (right, the moving volume, models of its own),
// each in an axial view. Slice position, crosshair, zoom and window/level follow the other
// column in patient coordinates while linked (ComparisonModel: one Frame of Reference, or
// aligned by three or more point pairs). Keys: X swaps the columns' sides, F flickers (one
// column at a time in the whole width, each press the other), B (or Esc) shows both again.
#include <memory>

#include <QWidget>

#include "app_models.h"
#include "comparison_model.h"

class QCheckBox;
class QLabel;
class QPushButton;

namespace voxray::ui {

class SliceView;

// The prior's own models (its column): nothing of it touches the study's.
struct PriorColumn {
  VolumeDocument document;
  CrosshairModel crosshair;
  WindowLevelModel windowLevel;
  RenderStateModel render;
};

class CompareView : public QWidget {
  Q_OBJECT
 public:
  explicit CompareView(AppModels& study, QWidget* parent = nullptr);
  ~CompareView() override;

  // The prior in the right column; linking starts when the model says so.
  void setPrior(std::shared_ptr<const Volume> prior, const QString& name);
  bool hasPrior() const { return !prior_->document.empty(); }
  SliceView& fixedView() { return *fixedView_; }
  SliceView& movingView() { return *movingView_; }
  ComparisonModel& comparison() { return comparison_; }
  PriorColumn& prior() { return *prior_; }
  QString statusText() const;  // the link and the last alignment, as the bar shows them

  void swapSides();
  bool swapped() const { return swapped_; }
  void flicker();  // both -> fixed only -> moving only -> fixed only ...
  void sideBySide();
  int shownColumns() const;  // 0: both; 1: the fixed one only; 2: the moving one only
  // The crosshairs' positions as a point pair (each in its own volume's LPS mm).
  void addPairAtCrosshairs();
  // alignPointPairs through the model; false with the message in the status on refusal.
  bool align();

 signals:
  void closeRequested();
  void statusChanged(const QString& text);

 protected:
  void keyPressEvent(QKeyEvent* e) override;

 private:
  void refreshGeometry();  // either volume changed
  void refreshStatus();
  void placeColumns();

  AppModels& study_;
  std::unique_ptr<PriorColumn> prior_;
  ComparisonModel comparison_;
  std::unique_ptr<ComparisonLink> link_;
  SliceView* fixedView_;
  SliceView* movingView_;
  QWidget *fixedColumn_, *movingColumn_;
  QLabel *fixedName_, *movingName_, *status_;
  QCheckBox *linkBox_, *wlBox_;
  bool swapped_ = false;
  int shown_ = 0;
  QString message_;  // the last alignment's outcome
  int docConnection_ = 0, modelConnection_ = 0;
};

}  // namespace voxray::ui
