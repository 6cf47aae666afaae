#pragma once
// Compare (issue 36): today's study (left, the fixed volume: the window's own document,
// crosshair and window/level) beside a prior (right, the moving volume, models of its own),
// each in an axial view over a 3D view. Slice position, crosshair, zoom, window/level and
// the 3D camera follow the other column in patient coordinates while linked
// (ComparisonModel: one Frame of Reference, or aligned by point pairs or by dragging); the
// 3D look (transfer function, preset, lighting) follows unless "Link 3D look" is unticked.
// The study's 3D view renders through the window's scheduler (its render thread), the
// prior's through a render thread of its own. "Move prior" (M) turns left drags in either
// slice view into moving the prior (prior_move.h; Shift: turning it about the crosshair),
// each drag one step for Undo move / Redo move (and, while Move prior is on, Ctrl+Z and
// Ctrl+Shift+Z in compare). Keys: X swaps the columns' sides, F flickers
// (one column at a time in the whole width, each press the other), B (or Esc) shows both.
#include <memory>
#include <optional>

#include <QWidget>

#include "app_models.h"
#include "camera_link.h"
#include "comparison_model.h"
#include "prior_move.h"

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace voxray::ui {

class RenderScheduler;
class SliceView;
class VolumeView;

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
  // STUDYSCHEDULER: the window's, which renders the study's 3D view.
  CompareView(AppModels& study, RenderScheduler& studyScheduler, QWidget* parent = nullptr);
  ~CompareView() override;

  // The prior in the right column; linking starts when the model says so.
  void setPrior(std::shared_ptr<const Volume> prior, const QString& name);
  // A 4D prior: every time point; OWNTIME is shown while it does not follow the study's time
  // slider (time_follow.h: it follows when both have as many time points).
  void setPrior(VolumeSeries series, const QString& name, int ownTime = 0);
  QSpinBox* priorTimeBox() const { return priorTimeBox_; }
  const TimeFollow& priorTime() const { return priorTime_; }
  bool hasPrior() const { return !prior_->document.empty(); }
  SliceView& fixedView() { return *fixedView_; }
  SliceView& movingView() { return *movingView_; }
  VolumeView& fixed3dView() { return *fixed3d_; }
  VolumeView& moving3dView() { return *moving3d_; }
  RenderScheduler& priorScheduler() { return *priorScheduler_; }
  // The 3D views' link: while the view is shown (none while hidden).
  RenderLink* renderLink() { return renderLink_.get(); }
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
  // Move prior: left drags in the slice views move the prior (Shift: turn it).
  void setMovePrior(bool on);
  bool movePrior() const { return moveMode_; }
  const PriorMoveHistory& moveHistory() const { return history_; }
  PriorMoveHistory& moveHistory() { return history_; }  // Edit → Undo takes its steps too
  // The "Link 3D look" box (a session sets it).
  bool lookLinked() const;
  void setLookLinked(bool on);
  void undoMove();
  void redoMove();

 signals:
  void closeRequested();
  void statusChanged(const QString& text);

 protected:
  void keyPressEvent(QKeyEvent* e) override;
  bool eventFilter(QObject* watched, QEvent* e) override;
  void showEvent(QShowEvent* e) override;
  void hideEvent(QHideEvent* e) override;

 private:
  void refreshGeometry();  // either volume changed
  void refreshStatus();
  void placeColumns();
  void followStudyTime();  // the prior's time point by priorTime_, and the box
  // compare_move.cpp: a Move prior drag in a slice view (true: the event was taken).
  bool moveDrag(SliceView& view, QEvent* e);
  ScreenPlane screenPlane(SliceView& view, ComparisonModel::Side side) const;
  void refreshMoveButtons();
  bool undoKeyPressed(QKeyEvent* e);  // Ctrl+Z / Ctrl+Shift+Z in Move prior mode

  AppModels& study_;
  std::unique_ptr<PriorColumn> prior_;
  ComparisonModel comparison_;
  std::unique_ptr<ComparisonLink> link_;
  std::unique_ptr<RenderLink> renderLink_;
  RenderScheduler& studyScheduler_;
  std::unique_ptr<RenderScheduler> priorScheduler_;  // goes before prior_ (bound to it)
  SliceView* fixedView_;
  SliceView* movingView_;
  VolumeView *fixed3d_, *moving3d_;
  QWidget *fixedColumn_, *movingColumn_;
  QLabel *fixedName_, *movingName_, *status_;
  QCheckBox *linkBox_, *wlBox_, *lookBox_;
  QPushButton *moveButton_, *undoButton_, *redoButton_;
  QSpinBox* priorTimeBox_;
  TimeFollow priorTime_;
  bool moveMode_ = false;
  PriorMoveHistory history_;
  // The Move prior drag under way: where it started and what it started from.
  struct MoveDrag {
    ComparisonModel::Side side;
    bool turn;
    glm::dvec2 fromPx;
    ScreenPlane plane;
    PriorPlacement before;
    bool moved;
  };
  std::optional<MoveDrag> moveDrag_;
  bool swapped_ = false;
  int shown_ = 0;
  QString message_;  // the last alignment's outcome
  int docConnection_ = 0, modelConnection_ = 0, timeConnection_ = 0, cameraConnection_ = 0,
      historyConnection_ = 0;
};

}  // namespace voxray::ui
