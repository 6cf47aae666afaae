#pragma once
// The 2D transfer-function editor's drawing (issue 35): the volume's value x |gradient|
// histogram (Tf2dHistogram, log counts as grey) with the Tf2d's rectangles and triangles over
// it (outline and translucent fill in their colour). Drag a body to move it, a corner handle to
// resize it; the right-click menu adds a rectangle or triangle at the mouse, deletes, or picks
// a colour; Delete removes the selected one. Edits go to the TfEditorModel (undo steps, the 3D
// view follows); this widget keeps only how the axes are shown.
#include <functional>
#include <optional>

#include <QImage>
#include <QMenu>
#include <QWidget>

#include "tf2d_edit.h"
#include "tf2d_histogram.h"
#include "tf_editor_model.h"

namespace voxray::ui {

class Tf2dView : public QWidget {
 public:
  Tf2dView(TfEditorModel& model, QWidget* parent = nullptr);

  // The histogram sets both axes (HU: the volume's range; |gradient|: 0 ... its top). Empty:
  // no image, axes -1024 ... 3071 HU and 0 ... 200 HU/mm.
  void setHistogram(const Tf2dHistogram& h);
  double huLo() const { return huLo_; }
  double huHi() const { return huHi_; }
  double gradientTop() const { return gTop_; }

  // Where things are drawn, in widget pixels (tests drag there).
  QRectF plotArea() const;
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
  void contextMenuEvent(QContextMenuEvent* e) override;

 private:
  void addAt(Tf2dShape shape, QPointF pos);
  std::optional<Tf2dHit> hitAt(QPointF pos) const;

  TfEditorModel& model_;
  QImage image_;  // the log histogram, one pixel a bin, row 0 at the top (the highest |gradient|)
  double huLo_ = -1024.0, huHi_ = 3071.0, gTop_ = 200.0;
  std::optional<size_t> selection_;
  std::optional<Tf2dHit> drag_;
  QPointF dragFrom_;
  Tf2dPrimitive dragStart_;  // the shape as the drag found it
};

}  // namespace voxray::ui
