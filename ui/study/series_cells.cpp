#include "series_cells.h"

#include <algorithm>

#include "study_state.h"
#include "voxray/io/volume.h"

namespace voxray {

std::vector<PlacedView> cellsToOpen(const ReadingLayout& l, const std::string& shown) {
  std::vector<PlacedView> out;
  if (seriesInCells(l).size() <= 2) return out;
  for (const LayoutCell& c : layoutCells(l.layout))
    for (const PlacedView& p : l.placed)
      if (p.view == c.view && !p.series.empty() && p.series != shown) out.push_back(p);
  return out;
}

SeriesCells::SeriesCells(VolumeDocument& main, CrosshairModel& mainCrosshair,
                         RenderStateModel& mainRender)
    : main_(main), mainCrosshair_(mainCrosshair), mainRender_(mainRender) {
  // Another main volume (a session, the next series): each cell's link maps from it anew.
  mainConn_ = main_.changed.connect([this] {
    for (auto& c : cells_) refreshGeometry(*c);
  });
}

SeriesCells::~SeriesCells() {
  main_.changed.disconnect(mainConn_);
  cells_.clear();  // the links go before the crosshairs they hold
}

namespace {
bool same(const SeriesCell& c, const PlacedView& p) {
  return c.placed.view == p.view && c.placed.series == p.series;
}
}  // namespace

std::vector<GridView> SeriesCells::leaving(const std::vector<PlacedView>& wanted) const {
  std::vector<GridView> out;
  for (const auto& c : cells_)
    if (std::none_of(wanted.begin(), wanted.end(),
                     [&](const PlacedView& p) { return same(*c, p); }))
      out.push_back(c->placed.view);
  return out;
}

std::vector<GridView> SeriesCells::setCells(const std::vector<PlacedView>& wanted) {
  std::vector<std::unique_ptr<SeriesCell>> next;
  std::vector<GridView> added;
  for (const PlacedView& p : wanted) {
    auto it =
        std::find_if(cells_.begin(), cells_.end(), [&](const auto& c) { return c && same(*c, p); });
    if (it != cells_.end()) {
      next.push_back(std::move(*it));
      next.back()->placed = p;  // its note and description as now placed
      continue;
    }
    auto c = std::make_unique<SeriesCell>();
    c->placed = p;
    c->link = std::make_unique<ComparisonLink>(c->comparison, mainCrosshair_, c->crosshair);
    c->renderLink = std::make_unique<RenderLink>(c->comparison, mainRender_, c->render);
    next.push_back(std::move(c));
    added.push_back(p.view);
  }
  cells_ = std::move(next);  // the cells not wanted go (their links first: member order)
  return added;
}

SeriesCell* SeriesCells::cell(GridView view) {
  for (auto& c : cells_)
    if (c->placed.view == view) return c.get();
  return nullptr;
}

const SeriesCell* SeriesCells::cell(GridView view) const {
  return const_cast<SeriesCells*>(this)->cell(view);
}

bool SeriesCells::setVolume(GridView view, VolumeSeries series, const std::string& name) {
  SeriesCell* c = cell(view);
  if (!c || series.empty() || !series.front()) return false;
  const Volume& first = *series.front();
  c->crosshair.setGeometry(first.dims, first.spacingMm, first.direction);
  const InitialWindow w = initialWindow(first);
  c->windowLevel.reset(w.wl, w.source);
  c->document.setSeries(std::move(series), name);
  refreshGeometry(*c);
  return true;
}

void SeriesCells::refreshGeometry(SeriesCell& c) {
  if (main_.empty() || c.document.empty()) return;
  // setGeometries notifies the link, which puts the cell's crosshair on the main one's point.
  c.comparison.setGeometries(VolumeGeometry::of(*main_.volume()),
                             VolumeGeometry::of(*c.document.volume()));
  c.link->syncMovingToFixed();
  c.renderLink->syncMovingToFixed();
}

}  // namespace voxray
