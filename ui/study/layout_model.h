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

}  // namespace voxray
