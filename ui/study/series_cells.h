#pragma once
// More than two series in one layout (issue 37): each view a hanging protocol (or a session)
// fills with another series than the main document's gets a cell of its own: the series'
// document, crosshair, window/level and render state, as compare's prior column has. Its
// crosshair follows the main one, and the main one follows it, in patient coordinates (LPS
// mm) through a ComparisonModel and ComparisonLink of its own while the two share a Frame of
// Reference; so every cell shows the same patient point. Window/level stays each cell's own
// (the series may differ in their values). The widgets show each cell's slice view in its
// grid position (ReadingActions); one or two series stay the grid's and compare's.
#include <memory>
#include <string>
#include <vector>

#include "camera_link.h"
#include "comparison_model.h"
#include "crosshair_model.h"
#include "layout_model.h"
#include "no_qt.h"
#include "render_state_model.h"
#include "time_series.h"
#include "volume_document.h"
#include "window_level.h"

namespace voxray {

struct SeriesCell {
  PlacedView placed;  // its view and its series
  VolumeDocument document;
  CrosshairModel crosshair;
  WindowLevelModel windowLevel;
  RenderStateModel render;
  ComparisonModel comparison;  // fixed: the main document; moving: this cell's
  std::unique_ptr<ComparisonLink> link;
  // Its 3D look and camera follow the main one's (and the main camera its), as compare's
  // prior column: for a cell shown in 3D.
  std::unique_ptr<RenderLink> renderLink;
};

// The views of L that need a cell of their own with SHOWN as the main document's series:
// those holding another series, when L places more than two different series (one or two:
// the grid's views and compare's columns show them). In L's cell order.
std::vector<PlacedView> cellsToOpen(const ReadingLayout& l, const std::string& shown);

class SeriesCells {
 public:
  // MAIN, its crosshair and render state: the main document the cells are linked to (they
  // outlive this).
  SeriesCells(VolumeDocument& main, CrosshairModel& mainCrosshair, RenderStateModel& mainRender);
  ~SeriesCells();
  SeriesCells(const SeriesCells&) = delete;
  SeriesCells& operator=(const SeriesCells&) = delete;

  // The views whose cells setCells(WANTED) removes (their widgets must go first).
  std::vector<GridView> leaving(const std::vector<PlacedView>& wanted) const;
  // The cells of WANTED: a cell already showing the same series in the same view is kept
  // (its volume and window); the others go. Returns the views of the new cells (empty until
  // setVolume).
  std::vector<GridView> setCells(const std::vector<PlacedView>& wanted);
  void clear() { setCells({}); }

  // VIEW's cell shows SERIES: its crosshair and 3D camera on the main one's patient point
  // (when linked), its 3D look the main one's, its window the series' own. False: VIEW has no cell
  // (it went while the series loaded).
  bool setVolume(GridView view, VolumeSeries series, const std::string& name);

  SeriesCell* cell(GridView view);
  const SeriesCell* cell(GridView view) const;
  const std::vector<std::unique_ptr<SeriesCell>>& cells() const { return cells_; }
  bool empty() const { return cells_.empty(); }

 private:
  void refreshGeometry(SeriesCell& c);  // the main or the cell's volume changed
  VolumeDocument& main_;
  CrosshairModel& mainCrosshair_;
  RenderStateModel& mainRender_;
  std::vector<std::unique_ptr<SeriesCell>> cells_;
  int mainConn_ = 0;
};

}  // namespace voxray
