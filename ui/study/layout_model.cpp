#include "layout_model.h"

#include <algorithm>
#include <cctype>

namespace voxray {

const std::vector<ViewLayout>& viewLayouts() {
  static const std::vector<ViewLayout> all = {ViewLayout::One,       ViewLayout::OneByTwo,
                                              ViewLayout::TwoByTwo,  ViewLayout::OnePlusThree,
                                              ViewLayout::MprPlus3d, ViewLayout::ThreeDOnly};
  return all;
}

std::string layoutName(ViewLayout l) {
  switch (l) {
    case ViewLayout::One:
      return "1x1";
    case ViewLayout::OneByTwo:
      return "1x2";
    case ViewLayout::TwoByTwo:
      return "2x2";
    case ViewLayout::OnePlusThree:
      return "1+3";
    case ViewLayout::MprPlus3d:
      return "mpr+3d";
    case ViewLayout::ThreeDOnly:
      return "3d";
  }
  return "mpr+3d";
}

std::string layoutTitle(ViewLayout l) {
  switch (l) {
    case ViewLayout::One:
      return "1×1 (axial)";
    case ViewLayout::OneByTwo:
      return "1×2 (axial and 3D)";
    case ViewLayout::TwoByTwo:
      return "2×2 (slices first)";
    case ViewLayout::OnePlusThree:
      return "1+3 (large axial)";
    case ViewLayout::MprPlus3d:
      return "MPR+3D";
    case ViewLayout::ThreeDOnly:
      return "3D only";
  }
  return "";
}

std::optional<ViewLayout> parseLayout(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  for (ViewLayout l : viewLayouts())
    if (layoutName(l) == lower) return l;
  return std::nullopt;
}

std::vector<LayoutCell> layoutCells(ViewLayout l) {
  using V = GridView;
  switch (l) {
    case ViewLayout::One:
      return {{V::Axial, 0, 0}};
    case ViewLayout::OneByTwo:
      return {{V::Axial, 0, 0}, {V::Volume3d, 0, 1}};
    case ViewLayout::TwoByTwo:
      return {{V::Axial, 0, 0}, {V::Coronal, 0, 1}, {V::Sagittal, 1, 0}, {V::Volume3d, 1, 1}};
    case ViewLayout::OnePlusThree:
      // The large view spans three rows of two columns; the small ones stack on the right.
      return {{V::Axial, 0, 0, 3, 2}, {V::Coronal, 0, 2}, {V::Sagittal, 1, 2}, {V::Volume3d, 2, 2}};
    case ViewLayout::MprPlus3d:
      return {{V::Volume3d, 0, 0}, {V::Axial, 0, 1}, {V::Coronal, 1, 0}, {V::Sagittal, 1, 1}};
    case ViewLayout::ThreeDOnly:
      return {{V::Volume3d, 0, 0}};
  }
  return {};
}

std::string gridViewName(GridView v) {
  switch (v) {
    case GridView::Volume3d:
      return "3d";
    case GridView::Axial:
      return "axial";
    case GridView::Coronal:
      return "coronal";
    case GridView::Sagittal:
      return "sagittal";
  }
  return "axial";
}

const std::vector<GridView>& gridViews() {
  static const std::vector<GridView> all = {GridView::Volume3d, GridView::Axial, GridView::Coronal,
                                            GridView::Sagittal};
  return all;
}

std::optional<GridView> parseGridView(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  for (GridView v : gridViews())
    if (gridViewName(v) == lower) return v;
  return std::nullopt;
}

std::vector<LayoutCell> visibleCells(const ReadingLayout& l) {
  std::vector<LayoutCell> out;
  for (const LayoutCell& c : layoutCells(l.layout)) {
    auto it = std::find_if(l.placed.begin(), l.placed.end(),
                           [&](const PlacedView& p) { return p.view == c.view; });
    if (it == l.placed.end() || !it->series.empty()) out.push_back(c);
  }
  return out;
}

std::vector<std::string> emptyViewNotes(const ReadingLayout& l) {
  std::vector<std::string> out;
  for (const LayoutCell& c : layoutCells(l.layout))
    for (const PlacedView& p : l.placed)
      if (p.view == c.view && p.series.empty()) out.push_back(gridViewName(p.view) + ": " + p.note);
  return out;
}

std::vector<std::string> seriesInCells(const ReadingLayout& l) {
  std::vector<std::string> out;
  for (const LayoutCell& c : layoutCells(l.layout))
    for (const PlacedView& p : l.placed)
      if (p.view == c.view && !p.series.empty() &&
          std::find(out.begin(), out.end(), p.series) == out.end())
        out.push_back(p.series);
  return out;
}

ReadingLayout placeInView(ReadingLayout l, GridView view, const StudySeries& s) {
  auto it = std::find_if(l.placed.begin(), l.placed.end(),
                         [&](const PlacedView& p) { return p.view == view; });
  if (it == l.placed.end()) {
    l.placed.push_back(PlacedView{});
    it = l.placed.end() - 1;
  }
  *it = PlacedView{view, s.selector, s.description, "", s.uid};
  return l;
}

ReadingLayout checkPlacement(ReadingLayout l, const std::vector<StudySeries>& study) {
  for (PlacedView& p : l.placed) {
    if (p.series.empty()) continue;
    // The UID names the series wherever the folder's files moved; older sessions have none.
    const bool there = std::any_of(study.begin(), study.end(), [&](const StudySeries& s) {
      return p.uid.empty() ? s.selector == p.series : s.uid == p.uid;
    });
    if (there) continue;
    const std::string name = p.description.empty() ? p.series : p.description;
    p.note = "its series '" + name + "' is no longer in the study; the view is left empty";
    p.series.clear();
    p.uid.clear();
  }
  return l;
}

}  // namespace voxray
