#include "view_grid.h"

namespace voxray::ui {

ViewGrid::ViewGrid(QWidget* tl, QWidget* tr, QWidget* bl, QWidget* br, QWidget* parent)
    : QWidget(parent), views_{tl, tr, bl, br} {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setSpacing(2);
  for (int i = 0; i < 4; ++i) grid->addWidget(views_[i], i / 2, i % 2);
}

void ViewGrid::toggleMaximised(QWidget* view) {
  maximised_ = maximised_ == view || !views_.contains(view) ? nullptr : view;
  for (QWidget* v : views_) v->setVisible(!maximised_ || v == maximised_);
}

void ViewGrid::setMaximised(int index) {
  maximised_ = nullptr;
  toggleMaximised(index >= 0 && index < views_.size() ? views_[index] : nullptr);
}

int ViewGrid::maximisedIndex() const { return maximised_ ? int(views_.indexOf(maximised_)) : -1; }

}  // namespace voxray::ui
