#pragma once
// A series dragged from the study browser onto a view (issue 37): the browser's series rows
// carry it as mime data of their own type; each slice and 3D view of the workstation (the
// grid's cells and compare's columns) takes the drop through SeriesDropFilter and opens the
// series there (ReadingActions::dropSeries says where it goes).
#include <functional>
#include <optional>

#include <QObject>
#include <QString>

class QMimeData;

namespace voxray::ui {

// What a series row carries: how the loader opens it (the folder and LoadOptions::series),
// and its Series Instance UID and description for the user.
struct SeriesDrag {
  QString folder, series, uid, description;
};

inline constexpr char kSeriesMimeType[] = "application/x-voxray-series";

// The mime data of D (JSON in kSeriesMimeType); the caller owns it (QDrag takes it).
QMimeData* seriesMimeData(const SeriesDrag& d);
// The series M carries; none when M is no series (files, text) or names no folder.
std::optional<SeriesDrag> seriesFromMime(const QMimeData* m);

// Makes a widget take series drops: accepts drags of kSeriesMimeType (others go on to the
// window, which opens dropped files) and gives each drop to DROPPED with the widget.
class SeriesDropFilter : public QObject {
  Q_OBJECT
 public:
  using Dropped = std::function<void(QWidget* view, const SeriesDrag& d)>;
  explicit SeriesDropFilter(Dropped dropped, QObject* parent = nullptr);
  void watch(QWidget* view);  // sets acceptDrops and filters its drag and drop events

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override;

 private:
  Dropped dropped_;
};

}  // namespace voxray::ui
