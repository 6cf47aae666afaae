#pragma once
// The 2x2 layout of the 3D view and the three slice views. Any view can be maximised and
// restored (double-click on it, or toggleMaximised for the focused one).
#include <QGridLayout>
#include <QWidget>

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

 private:
  QList<QWidget*> views_;
  QWidget* maximised_ = nullptr;
};

}  // namespace voxray::ui
