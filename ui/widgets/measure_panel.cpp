#include "measure_panel.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include "coupling.h"

namespace voxray::ui {

namespace {

struct ToolChoice {
  MeasureTool tool;
  const char* label;
  const char* tip;
};
constexpr ToolChoice kTools[] = {
    {MeasureTool::None, "Pointer", "Left drag moves the crosshair; handles stay draggable"},
    {MeasureTool::Distance, "Distance", "Drag from one point to the other (mm)"},
    {MeasureTool::Angle, "Angle", "Drag the first arm to the vertex, then click its end"},
    {MeasureTool::Ellipse, "Ellipse", "Drag across the ellipse's bounding box: mean, SD, area"},
    {MeasureTool::Rect, "Rectangle", "Drag from corner to corner: mean, SD, area"},
    {MeasureTool::Text, "Text", "Click where the text goes, type it, Return (T)"},
    {MeasureTool::Arrow, "Arrow", "Drag from the arrow's head to its tail (W)"}};

QWidget* makeToolRow(MeasurementModel& m) {
  auto* row = new QWidget;
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* group = new QButtonGroup(row);
  for (const ToolChoice& t : kTools) {
    auto* b = new QToolButton;
    b->setText(t.label);
    b->setToolTip(t.tip);
    b->setCheckable(true);
    b->setObjectName(QString("measureTool") + t.label);
    group->addButton(b, int(t.tool));
    layout->addWidget(b);
  }
  auto refresh = [group, &m] {
    if (auto* b = group->button(int(m.tool()))) b->setChecked(true);
  };
  refresh();
  onModelChange<>(row, m.changed, refresh);
  QObject::connect(group, &QButtonGroup::idClicked, row,
                   [&m](int id) { m.setTool(MeasureTool(id)); });
  return row;
}

}  // namespace

namespace {

// The annotations' list and its Delete button.
QWidget* makeAnnotationList(AnnotationModel& a) {
  auto* box = new QWidget;
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel("Annotations"));
  auto* list = new QListWidget;
  list->setObjectName("annotationList");
  list->setToolTip("Text and arrows of the slice views; select one to highlight it");
  auto* remove = new QPushButton("Delete annotation");
  remove->setObjectName("annotationDelete");
  remove->setToolTip(
      "Remove the selected annotation (Del in a slice view; Edit > Undo brings it back)");
  layout->addWidget(list);
  layout->addWidget(remove);
  auto refresh = [list, remove, &a] {
    QSignalBlocker block(list);
    list->clear();
    for (const Annotation& item : a.items()) {
      const QString text = QString::fromStdString(item.text);
      auto* row = new QListWidgetItem(
          item.isArrow() ? (text.isEmpty() ? QString("arrow") : "arrow  " + text) : "text  " + text,
          list);
      row->setData(Qt::UserRole, item.id);
      if (item.id == a.selected()) list->setCurrentItem(row);
    }
    remove->setEnabled(a.selected() != 0);
  };
  refresh();
  onModelChange<>(box, a.changed, refresh);
  QObject::connect(list, &QListWidget::currentItemChanged, box, [&a](QListWidgetItem* item) {
    if (item) a.select(item->data(Qt::UserRole).toInt());
  });
  QObject::connect(remove, &QPushButton::clicked, box, [&a] {
    if (a.selected()) a.remove(a.selected());
  });
  return box;
}

}  // namespace

QDockWidget* makeMeasurementDock(MeasurementModel& m, AnnotationModel& a, VolumeDocument& doc) {
  auto* dock = new QDockWidget("Measurements");
  dock->setObjectName("measurementDock");
  auto* body = new QWidget;
  auto* layout = new QVBoxLayout(body);
  layout->addWidget(makeToolRow(m));
  auto* list = new QListWidget;
  list->setObjectName("measurementList");
  list->setToolTip("Select a measurement to highlight it; Del removes it");
  layout->addWidget(list);
  auto* remove = new QPushButton("Delete");
  remove->setObjectName("measurementDelete");
  remove->setToolTip("Remove the selected measurement (Del in a slice view)");
  auto* exports = new QCheckBox("Show measurements in exports");
  exports->setObjectName("measurementsInExports");
  exports->setToolTip("Burn the measurements into exported slice images (off: the image only)");
  auto* hint = new QLabel("3D: Ctrl+click two points on the iso surface for a distance.");
  hint->setWordWrap(true);
  layout->addWidget(remove);
  layout->addWidget(exports);
  layout->addWidget(hint);
  layout->addWidget(makeAnnotationList(a));
  dock->setWidget(body);

  auto refresh = [list, exports, remove, &m, &doc] {
    QSignalBlocker b1(list), b2(exports);
    list->clear();
    for (const Measurement& item : m.items()) {
      QString text = QString("%1  %2").arg(toString(item.kind));
      text = text.arg(doc.empty() ? QString("—")
                                  : QString::fromStdString(measurementText(*doc.volume(), item)));
      auto* row = new QListWidgetItem(text, list);
      row->setData(Qt::UserRole, item.id);
      if (item.id == m.selected()) list->setCurrentItem(row);
    }
    exports->setChecked(m.showInExports());
    remove->setEnabled(m.selected() != 0);
  };
  refresh();
  onModelChange<>(dock, m.changed, refresh);
  onModelChange<>(dock, doc.timeChanged, refresh);  // an ROI's statistics at the time point
  QObject::connect(list, &QListWidget::currentItemChanged, dock, [&m](QListWidgetItem* item) {
    if (item) m.select(item->data(Qt::UserRole).toInt());
  });
  QObject::connect(remove, &QPushButton::clicked, dock, [&m] {
    if (m.selected()) m.remove(m.selected());
  });
  QObject::connect(exports, &QCheckBox::toggled, dock, [&m](bool on) { m.setShowInExports(on); });
  return dock;
}

}  // namespace voxray::ui
