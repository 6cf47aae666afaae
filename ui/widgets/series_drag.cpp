#include "series_drag.h"

#include <QDragEnterEvent>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMimeData>
#include <QWidget>

namespace voxray::ui {

QMimeData* seriesMimeData(const SeriesDrag& d) {
  auto* m = new QMimeData;
  const QJsonObject o{
      {"folder", d.folder}, {"series", d.series}, {"uid", d.uid}, {"description", d.description}};
  m->setData(kSeriesMimeType, QJsonDocument(o).toJson(QJsonDocument::Compact));
  m->setText(d.description);  // what a text field shows when the row is dropped there
  return m;
}

std::optional<SeriesDrag> seriesFromMime(const QMimeData* m) {
  if (!m || !m->hasFormat(kSeriesMimeType)) return std::nullopt;
  const QJsonObject o = QJsonDocument::fromJson(m->data(kSeriesMimeType)).object();
  SeriesDrag d{o.value("folder").toString(), o.value("series").toString(),
               o.value("uid").toString(), o.value("description").toString()};
  if (d.folder.isEmpty()) return std::nullopt;
  return d;
}

SeriesDropFilter::SeriesDropFilter(Dropped dropped, QObject* parent)
    : QObject(parent), dropped_(std::move(dropped)) {}

void SeriesDropFilter::watch(QWidget* view) {
  view->setAcceptDrops(true);
  view->installEventFilter(this);
}

bool SeriesDropFilter::eventFilter(QObject* watched, QEvent* e) {
  switch (e->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
      auto* d = static_cast<QDragMoveEvent*>(e);         // QDragEnterEvent is one
      if (!seriesFromMime(d->mimeData())) return false;  // files: the window's drop
      d->acceptProposedAction();
      return true;
    }
    case QEvent::Drop: {
      auto* d = static_cast<QDropEvent*>(e);
      const auto series = seriesFromMime(d->mimeData());
      if (!series) return false;
      d->acceptProposedAction();
      dropped_(static_cast<QWidget*>(watched), *series);
      return true;
    }
    default:
      return false;
  }
}

}  // namespace voxray::ui
