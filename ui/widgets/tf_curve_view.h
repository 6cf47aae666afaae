#pragma once
// The transfer-function editor's drawing (issue 35): the volume's histogram over HU (linear or
// log), the opacity curve over it with its points, and the colour bar under it with the colour
// points. Click adds a point, drag moves it, Delete or a right click removes it, a double
// click on a colour point picks its colour. The HU axis under the colour bar zooms: the wheel
// (anywhere; over the axis or with Ctrl as well) zooms about the HU under the cursor, a drag
// along the axis strip or with the middle button pans (axis_zoom.h). Edits go to the
// TfEditorModel; this widget keeps only how the axes are shown.
#include <optional>

#include <QWidget>

#include "axis_zoom.h"
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
  double huLo() const { return hu_.lo; }
  double huHi() const { return hu_.hi; }
  double huPerPixel() const;
  // The range "reset" goes back to (the dialog sets the volume's), and "fit to the visible
  // range": the HU that hold voxels (visibleHuRange of the histogram; nothing without one).
  void setFullRange(double lo, double hi) { full_ = {lo, hi}; }
  void resetRange() { setHuRange(full_.lo, full_.hi); }
  void fitVisible();
  // Asked when the HU axis changes (zoom, pan, fit), so the dialog's fields follow.
  std::function<void()> rangeChanged;

  // Where things are drawn, in widget pixels (tests click there).
  QRectF curveArea() const;
  QRectF colorBar() const;
  QRectF axisStrip() const;  // the HU axis' labels under the colour bar: wheel and drag there
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
  AxisRange hu_{-1024.0, 3071.0}, full_{-1024.0, 3071.0};
  double top_ = 1.0;
  std::optional<Selection> selection_;
  bool dragging_ = false;
  // A pan: from where, and the range it started with (each move pans from there: exact).
  std::optional<std::pair<double, AxisRange>> pan_;
};

}  // namespace voxray::ui
