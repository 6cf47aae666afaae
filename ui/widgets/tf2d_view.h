#pragma once
// The 2D transfer-function editor's drawing (issue 35): the volume's value x |gradient|
// histogram (Tf2dHistogram, log counts as grey) with the Tf2d's rectangles and triangles over
// it (outline and translucent fill in their colour). Drag a body to move it, a corner handle to
// resize it; the right-click menu adds a rectangle or triangle at the mouse, deletes, or picks
// a colour; Delete removes the selected one. Both axes zoom (axis_zoom.h): the wheel over the
// HU axis (the strip under the plot) or the gradient axis (the strip left of it) zooms that
// axis, over the plot (with or without Ctrl) both, about the value under the cursor; a drag
// along a strip pans its axis, a middle-button drag pans both. Edits go to the TfEditorModel
// (undo steps, the 3D view follows); this widget keeps only how the axes are shown.
#include <functional>
#include <optional>

#include <QImage>
#include <QMenu>
#include <QWidget>

#include "axis_zoom.h"
#include "tf2d_edit.h"
#include "tf2d_histogram.h"
#include "tf_editor_model.h"

namespace voxray::ui {

class Tf2dView : public QWidget {
 public:
  Tf2dView(TfEditorModel& model, QWidget* parent = nullptr);

  // The histogram sets both axes (HU: the volume's range; |gradient|: 0 ... its top). Empty:
  // no image, axes -1024 ... 3071 HU and 0 ... 200 HU/mm.
  // Also resets both axes.
  void setHistogram(const Tf2dHistogram& h);
  double huLo() const { return hu_.lo; }
  double huHi() const { return hu_.hi; }
  double gradientLo() const { return g_.lo; }
  double gradientTop() const { return g_.hi; }
  void setRanges(AxisRange hu, AxisRange g);
  // The histogram's whole axes, or where it holds voxels (occupiedRange of its column and
  // row sums at kVisibleFraction; the gradient axis from 0).
  void resetRanges();
  void fitVisible();

  // Where things are drawn, in widget pixels (tests drag there).
  QRectF plotArea() const;
  QRectF huStrip() const;        // under the plot: the HU axis' wheel and drag
  QRectF gradientStrip() const;  // left of the plot: the gradient axis'
  double xOf(double hu) const;
  double yOf(double g) const;
  double huAt(double x) const;
  double gAt(double y) const;

  std::optional<size_t> selection() const { return selection_; }
  void select(std::optional<size_t> i);
  std::function<void()> selectionChanged;

  // The right-click menu at POS (widget pixels), with its actions named tf2dAddRect,
  // tf2dAddTriangle, tf2dDelete, tf2dColor (tests trigger them). The caller owns it.
  QMenu* menuAt(QPointF pos);
  // Asks the colour of primitive I (a QColorDialog by default).
  void pickColor(size_t i);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;
  void wheelEvent(QWheelEvent* e) override;
  void contextMenuEvent(QContextMenuEvent* e) override;

 private:
  void addAt(Tf2dShape shape, QPointF pos);
  std::optional<Tf2dHit> hitAt(QPointF pos) const;

  TfEditorModel& model_;
  QImage image_;  // the log histogram, one pixel a bin, row 0 at the top (the highest |gradient|)
  Tf2dHistogram histogram_;
  AxisRange hu_{-1024.0, 3071.0}, g_{0.0, 200.0};  // shown
  AxisRange fullHu_{-1024.0, 3071.0};              // the histogram's
  double fullG_ = 200.0;  // the histogram's gradient top: a new table's gradientMax
  struct Pan {
    QPointF from;
    AxisRange hu, g;
    bool panHu, panG;
  };
  std::optional<Pan> pan_;
  std::optional<size_t> selection_;
  std::optional<Tf2dHit> drag_;
  QPointF dragFrom_;
  Tf2dPrimitive dragStart_;  // the shape as the drag found it
};

}  // namespace voxray::ui
