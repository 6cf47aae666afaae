#pragma once
// The layout of the 3D view and the three slice views: the classic 2x2 grid, or any layout of
// layout_model.h (arrange). Any shown view can be maximised and restored (double-click on it,
// or toggleMaximised for the focused one).
#include <vector>

#include <QGridLayout>
#include <QWidget>

#include "layout_model.h"

namespace voxray::ui {

class ViewGrid : public QWidget {
  Q_OBJECT
 public:
  // Top left, top right, bottom left, bottom right.
  ViewGrid(QWidget* topLeft, QWidget* topRight, QWidget* bottomLeft, QWidget* bottomRight,
           QWidget* parent = nullptr);
  void toggleMaximised(QWidget* view);
  QWidget* maximised() const { return maximised_; }
  void setMaximised(int index);  // -1: all four (saved layout)
  int maximisedIndex() const;
  // Places the views (by GridView number: the constructor's order) in CELLS; the others hide.
  void arrange(const std::vector<LayoutCell>& cells);
  bool shows(QWidget* view) const { return shown_.contains(view); }
  // VIEW's grid position shows W (a series cell's own view; reading_actions.h) in place of
  // the constructor's view, which hides; nullptr gives the position back to it. The layout
  // is arranged again.
  void setCellView(GridView view, QWidget* w);
  QWidget* viewAt(GridView view) const { return views_[int(view)]; }

 private:
  QList<QWidget*> own_;    // the constructor's views
  QList<QWidget*> views_;  // what each position shows now
  std::vector<LayoutCell> cells_;
  QList<QWidget*> shown_;  // the current layout's views
  QWidget* maximised_ = nullptr;
};

}  // namespace voxray::ui
