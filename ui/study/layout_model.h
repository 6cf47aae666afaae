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
  bool operator==(const PlacedView&) const = default;
};

// The grid as the reader left it: the layout and, when a hanging protocol placed series, what
// each named view holds. Saved in sessions (Session::reading).
struct ReadingLayout {
  ViewLayout layout = ViewLayout::MprPlus3d;
  std::vector<PlacedView> placed;  // empty: every view shows the open volume
  bool operator==(const ReadingLayout&) const = default;
};

// L's cells less the views left empty (they are hidden; their cell stays blank).
std::vector<LayoutCell> visibleCells(const ReadingLayout& l);
// The notes of the views L left empty, one line each ("sagittal: no series matches 'STIR'").
std::vector<std::string> emptyViewNotes(const ReadingLayout& l);

}  // namespace voxray
