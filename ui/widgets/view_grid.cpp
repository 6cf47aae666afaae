#include "view_grid.h"

namespace voxray::ui {

ViewGrid::ViewGrid(QWidget* tl, QWidget* tr, QWidget* bl, QWidget* br, QWidget* parent)
    : QWidget(parent), own_{tl, tr, bl, br}, views_(own_), shown_(views_) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setSpacing(2);
  for (int i = 0; i < 4; ++i) grid->addWidget(views_[i], i / 2, i % 2);
  cells_ = layoutCells(ViewLayout::MprPlus3d);  // the places just given
}

void ViewGrid::toggleMaximised(QWidget* view) {
  maximised_ = maximised_ == view || !shown_.contains(view) ? nullptr : view;
  for (QWidget* v : views_) v->setVisible(maximised_ ? v == maximised_ : shown_.contains(v));
}

void ViewGrid::setMaximised(int index) {
  maximised_ = nullptr;
  toggleMaximised(index >= 0 && index < views_.size() ? views_[index] : nullptr);
}

int ViewGrid::maximisedIndex() const { return maximised_ ? int(views_.indexOf(maximised_)) : -1; }

void ViewGrid::setCellView(GridView view, QWidget* w) {
  QWidget* now = w ? w : own_[int(view)];
  QWidget* was = views_[int(view)];
  if (now == was) return;
  static_cast<QGridLayout*>(layout())->removeWidget(was);
  was->hide();
  shown_.removeAll(was);
  if (now->parentWidget() != this) now->setParent(this);
  views_[int(view)] = now;
  arrange(cells_);
}

void ViewGrid::arrange(const std::vector<LayoutCell>& cells) {
  cells_ = cells;
  auto* grid = static_cast<QGridLayout*>(layout());
  for (QWidget* v : views_) grid->removeWidget(v);
  // Stretch only the rows and columns this layout uses (a 1+3 has three rows).
  for (int i = 0; i < 4; ++i) {
    grid->setRowStretch(i, 0);
    grid->setColumnStretch(i, 0);
  }
  shown_.clear();
  for (const LayoutCell& c : cells) {
    QWidget* v = views_[int(c.view)];
    grid->addWidget(v, c.row, c.column, c.rowSpan, c.columnSpan);
    shown_ << v;
    for (int r = c.row; r < c.row + c.rowSpan; ++r) grid->setRowStretch(r, 1);
    for (int k = c.column; k < c.column + c.columnSpan; ++k) grid->setColumnStretch(k, 1);
  }
  maximised_ = nullptr;
  for (QWidget* v : views_) v->setVisible(shown_.contains(v));
}

}  // namespace voxray::ui
