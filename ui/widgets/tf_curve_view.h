#pragma once
// The transfer-function editor's drawing (issue 35): the volume's histogram over HU (linear or
// log), the opacity curve over it with its points, and the colour bar under it with the colour
// points. Click adds a point, drag moves it, Delete or a right click removes it, a double
// click on a colour point picks its colour, the wheel zooms the HU axis. Edits go to the
// TfEditorModel; this widget keeps only how the axes are shown.
#include <optional>

#include <QWidget>

#include "tf_editor_model.h"
#include "voxray/io/histogram.h"

namespace voxray::ui {

class TfCurveView : public QWidget {
 public:
  TfCurveView(TfEditorModel& model, QWidget* parent = nullptr);

  // The histogram of the open volume's stored values and the volume's slope and intercept
  // (its HU); an empty one draws none.
  void setHistogram(StoredHistogram h, double slope, double intercept);
  void setLogHistogram(bool on);
  // The HU axis shown, and the opacity at the top of the curve area (1, or less to shape
  // small opacities).
  void setHuRange(double lo, double hi);
  void setOpacityTop(double top);
  double huLo() const { return lo_; }
  double huHi() const { return hi_; }

  // Where things are drawn, in widget pixels (tests click there).
  QRectF curveArea() const;
  QRectF colorBar() const;
  double xOf(double hu) const;
  double yOf(double opacity) const;
  double huAt(double x) const;
  double opacityAt(double y) const;

  enum class List { Opacity, Color };
  struct Selection {
    List list;
    size_t index;
  };
  std::optional<Selection> selection() const { return selection_; }
  void select(std::optional<Selection> s);

  // Asked when the selection changes, so the dialog's fields follow.
  std::function<void()> selectionChanged;

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void mouseDoubleClickEvent(QMouseEvent* e) override;
  void wheelEvent(QWheelEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;

 private:
  std::optional<Selection> pointAt(QPointF pos) const;
  void removeSelected();
  void pickColor(size_t index);

  TfEditorModel& model_;
  StoredHistogram histogram_;
  double slope_ = 1.0, intercept_ = 0.0;
  bool logHistogram_ = true;
  double lo_ = -1024.0, hi_ = 3071.0, top_ = 1.0;
  std::optional<Selection> selection_;
  bool dragging_ = false;
};

}  // namespace voxray::ui
