#pragma once
// The view grid's layouts as data: which of the four views (the 3D view and the three slice
// views) takes which cells of the grid. The widgets only place them (ViewGrid::arrange).
#include <optional>
#include <string>
#include <vector>

#include "no_qt.h"

namespace voxray {

enum class ViewLayout { One, OneByTwo, TwoByTwo, OnePlusThree, MprPlus3d, ThreeDOnly };

// The views by number, as MainWindow builds them.
enum class GridView { Volume3d = 0, Axial = 1, Coronal = 2, Sagittal = 3 };

struct LayoutCell {
  GridView view;
  int row = 0, column = 0, rowSpan = 1, columnSpan = 1;
};

// Every layout in menu order.
const std::vector<ViewLayout>& viewLayouts();
// "1x1", "1x2", "2x2", "1+3", "mpr+3d", "3d": the names the rules' JSON and sessions use.
std::string layoutName(ViewLayout l);
// "1×1 (axial)" …: what the menu says.
std::string layoutTitle(ViewLayout l);
std::optional<ViewLayout> parseLayout(const std::string& name);  // case-insensitive
// The cells of L; views not listed are hidden. MprPlus3d is the workstation's classic grid
// (3D top left, axial, coronal, sagittal); TwoByTwo reads the three slices first (3D last).
std::vector<LayoutCell> layoutCells(ViewLayout l);

// "3d", "axial", "coronal", "sagittal": the views' names in rules and sessions.
std::string gridViewName(GridView v);
std::optional<GridView> parseGridView(const std::string& name);  // case-insensitive
const std::vector<GridView>& gridViews();                        // in that order

// What a hanging protocol put in one view: the series (its loader selector and description),
// or nothing, with the note saying why the view is empty.
struct PlacedView {
  GridView view = GridView::Axial;
  std::string series;       // LoadOptions::series of the series shown; empty: the view is empty
  std::string description;  // the series' description, for the user
  std::string note;         // why the view is empty ("no series matches 'STIR'")
  std::string uid{};        // its Series Instance UID (a session checks it still exists)
  bool operator==(const PlacedView&) const = default;
};

// The grid as the reader left it: the layout and, when a hanging protocol (or the user: Show
// series in this view) placed series, what each named view holds. Two different series show
// side by side (the first cell's series in the left column, the other in the right, linked in
// patient coordinates: compare); three or four each in its own cell (series_cells.h). Saved in
// sessions (Session::reading).
struct ReadingLayout {
  ViewLayout layout = ViewLayout::MprPlus3d;
  std::vector<PlacedView> placed;  // empty: every view shows the open volume
  bool operator==(const ReadingLayout&) const = default;
};

// L's cells less the views left empty (they are hidden; their cell stays blank).
std::vector<LayoutCell> visibleCells(const ReadingLayout& l);
// The notes of the views L left empty, one line each ("sagittal: no series matches 'STIR'").
std::vector<std::string> emptyViewNotes(const ReadingLayout& l);

// One volume series of the study, in the study's order (series number).
struct StudySeries {
  std::string selector;  // LoadOptions::series
  std::string description;
  std::string uid;  // Series Instance UID
};

// The series of L's cells in cell order, each once (the first: the left column).
std::vector<std::string> seriesInCells(const ReadingLayout& l);
// L with VIEW showing S (the user's Show series in this view; a series dropped on a cell).
ReadingLayout placeInView(ReadingLayout l, GridView view, const StudySeries& s);
// A session's placement checked against the series STUDY still has (by UID; by selector
// where the session has no UID): a view whose series is gone is left empty with a note naming
// the series; the rest stays as saved.
ReadingLayout checkPlacement(ReadingLayout l, const std::vector<StudySeries>& study);

}  // namespace voxray
