// Issue 37: a layout's cells exact, up to four series. A 2x2 rule naming four series puts the
// three that are not the main document's in cells of their own (cellsToOpen), each with its
// own volume, window and crosshair, the crosshairs linked to the main one in patient
// coordinates while they share a Frame of Reference (SeriesCells).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "hanging_protocol.h"
#include "series_cells.h"
#include "slice_geometry.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

const std::vector<StudySeries> kCellsStudy = {{"1", "AX T1", "1.2.3.1"},
                                              {"2", "AX T2", "1.2.3.2"},
                                              {"3", "AX FLAIR", "1.2.3.3"},
                                              {"4", "AX DWI", "1.2.3.4"}};

ReadingLayout fourSeries() {
  const HangingRule r =
      parseHangingProtocols(R"({"voxray-hanging-protocols": 1, "rules": [{"name": "4",
        "layout": "2x2", "series": {"axial": "T1", "coronal": "T2", "sagittal": "FLAIR",
        "3d": "DWI"}}]})")
          .rules.at(0);
  return ReadingLayout{ViewLayout::TwoByTwo, placeSeries(r, kCellsStudy)};
}

// A CT of 16 x 16 x SLICES voxels of 0.5 x 0.5 x SLICEMM mm, its first slice at z = Z0 mm,
// in Frame of Reference FOR, its file window at LEVEL (width 80).
std::shared_ptr<const Volume> ct(int slices, double sliceMm, double z0, const std::string& frame,
                                 double level) {
  auto v = std::make_shared<Volume>();
  v->dims = {16, 16, slices};
  v->spacingMm = {0.5, 0.5, sliceMm};
  v->originMm = {0.0, 0.0, z0};
  v->modality = "CT";
  v->study.frameOfReferenceUid = frame;
  v->window = DisplayWindow{80.0, level, "", "DICOM window"};
  v->voxels.assign(v->voxelCount(), 0);
  return v;
}

double patientZ(const VolumeDocument& d, const CrosshairModel& c) {
  return voxelToPatientMm(*d.volume(), c.centre()).z;
}

TEST(SeriesCells, FourSeriesOfA2x2RuleEachGetTheirNamedCell) {
  const ReadingLayout l = fourSeries();
  // The main document shows the first cell's series (axial: T1); the other three get cells,
  // in the layout's order, each with its own series.
  const auto cells = cellsToOpen(l, "1");
  ASSERT_EQ(cells.size(), size_t(3));
  EXPECT_EQ(cells[0].view, GridView::Coronal);
  EXPECT_EQ(cells[0].series, "2");
  EXPECT_EQ(cells[0].uid, "1.2.3.2");
  EXPECT_EQ(cells[1].view, GridView::Sagittal);
  EXPECT_EQ(cells[1].series, "3");
  EXPECT_EQ(cells[2].view, GridView::Volume3d);
  EXPECT_EQ(cells[2].series, "4");
  EXPECT_EQ(cells[2].description, "AX DWI");
  // Every view is shown: none is left empty.
  EXPECT_EQ(visibleCells(l).size(), size_t(4));
  EXPECT_TRUE(emptyViewNotes(l).empty());

  // Two series are compare's columns, not cells; one series is the grid's.
  ReadingLayout two = l;
  for (PlacedView& p : two.placed) p.series.assign(1, p.view == GridView::Coronal ? '2' : '1');
  EXPECT_TRUE(cellsToOpen(two, "1").empty());
  EXPECT_TRUE(cellsToOpen(ReadingLayout{ViewLayout::TwoByTwo, {}}, "").empty());
  // Three series (a view left empty: no series matched): two cells, the empty view none.
  ReadingLayout three = l;
  for (PlacedView& p : three.placed)
    if (p.view == GridView::Sagittal) p.series.clear();
  const auto threeCells = cellsToOpen(three, "1");
  ASSERT_EQ(threeCells.size(), size_t(2));
  EXPECT_EQ(threeCells[0].view, GridView::Coronal);
  EXPECT_EQ(threeCells[1].view, GridView::Volume3d);
}

TEST(SeriesCells, CellsKeepTheirSeriesAndOnlyChangedOnesAreNew) {
  VolumeDocument main;
  CrosshairModel mainCrosshair;
  RenderStateModel mainRender;
  SeriesCells cells(main, mainCrosshair, mainRender);
  const ReadingLayout l = fourSeries();
  const auto wanted = cellsToOpen(l, "1");
  EXPECT_TRUE(cells.leaving(wanted).empty());
  EXPECT_EQ(cells.setCells(wanted),
            (std::vector<GridView>{GridView::Coronal, GridView::Sagittal, GridView::Volume3d}));
  ASSERT_TRUE(cells.setVolume(GridView::Coronal, {ct(14, 10.0, 0.0, "1.2.for", 40.0)}, "T2"));
  SeriesCell* coronal = cells.cell(GridView::Coronal);
  ASSERT_TRUE(coronal);
  // The same placement again keeps every cell (the coronal one its volume); the sagittal view
  // showing another series is a new cell, the old one leaves.
  auto next = wanted;
  next[1].series = "1b";
  EXPECT_EQ(cells.leaving(next), std::vector<GridView>{GridView::Sagittal});
  EXPECT_EQ(cells.setCells(next), std::vector<GridView>{GridView::Sagittal});
  EXPECT_EQ(cells.cell(GridView::Coronal), coronal);
  EXPECT_FALSE(coronal->document.empty());
  EXPECT_EQ(cells.cell(GridView::Sagittal)->placed.series, "1b");
  EXPECT_TRUE(cells.cell(GridView::Sagittal)->document.empty());
  EXPECT_FALSE(cells.cell(GridView::Axial));  // the main document's: no cell
  // No series beyond two: every cell goes.
  cells.clear();
  EXPECT_TRUE(cells.empty());
  EXPECT_FALSE(cells.setVolume(GridView::Coronal, {ct(14, 10.0, 0.0, "1.2.for", 40.0)}, "T2"));
}

TEST(SeriesCells, CrosshairsFollowInPatientZWithinHalfASliceAndWindowsStayOwn) {
  VolumeDocument main;
  CrosshairModel mainCrosshair;
  const auto t1 = ct(28, 5.0, 0.0, "1.2.for", 40.0);  // 28 slices of 5 mm from z = 0
  mainCrosshair.setGeometry(t1->dims, t1->spacingMm, t1->direction);
  main.set(t1, "T1");
  RenderStateModel mainRender;
  mainRender.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 30.0; });
  SeriesCells cells(main, mainCrosshair, mainRender);
  cells.setCells(cellsToOpen(fourSeries(), "1"));
  // T2: 14 slices of 10 mm from z = 5 (the odd slices); FLAIR: 14 of 10 mm from z = 0 (the
  // even ones); DWI: another Frame of Reference (not linked: no alignment).
  ASSERT_TRUE(cells.setVolume(GridView::Coronal, {ct(14, 10.0, 5.0, "1.2.for", 100.0)}, "T2"));
  ASSERT_TRUE(cells.setVolume(GridView::Sagittal, {ct(14, 10.0, 0.0, "1.2.for", 200.0)}, "FL"));
  ASSERT_TRUE(cells.setVolume(GridView::Volume3d, {ct(20, 2.0, 0.0, "1.2.other", 300.0)}, "DWI"));
  SeriesCell& t2 = *cells.cell(GridView::Coronal);
  SeriesCell& flair = *cells.cell(GridView::Sagittal);
  SeriesCell& dwi = *cells.cell(GridView::Volume3d);
  EXPECT_TRUE(t2.comparison.linked() && flair.comparison.linked());
  EXPECT_FALSE(dwi.comparison.linked());
  // Each cell's window is its own series' (its file's level), not the main one's.
  EXPECT_DOUBLE_EQ(t2.windowLevel.value().level, 100.0);
  EXPECT_DOUBLE_EQ(flair.windowLevel.value().level, 200.0);
  EXPECT_DOUBLE_EQ(dwi.windowLevel.value().level, 300.0);

  const SliceAxes axial = sliceAxes(t1->direction, Orientation::Axial);
  const double dwiZ = patientZ(dwi.document, dwi.crosshair);
  // The linked cells' slices are 10 mm apart: each rounds to its own slice centres, so
  // within half of that (5 mm) of the main crosshair's z.
  auto expectFollow = [&](const char* what) {
    const double z = patientZ(main, mainCrosshair);
    for (SeriesCell* c : {&t2, &flair})
      EXPECT_LE(std::abs(patientZ(c->document, c->crosshair) - z), 5.0 + 1e-9)
          << what << ": " << c->placed.series << " at main z " << z;
  };
  expectFollow("opened");
  int moves = 0;
  for (int steps : {3, -1, 7, -4, 9, -20, 2}) {
    const double before = patientZ(main, mainCrosshair);
    mainCrosshair.scrollView(axial, steps);
    moves += patientZ(main, mainCrosshair) != before;
    expectFollow("main scrolled");
  }
  EXPECT_GE(moves, 6);  // the steps did move (the clamp at slice 0 may stop one)
  // Scrolling a cell moves the main one, and through it the other cell.
  for (int steps : {2, -3, 5}) {
    const double before = patientZ(t2.document, t2.crosshair);
    t2.crosshair.scrollView(sliceAxes(t2.document.volume()->direction, Orientation::Axial), steps);
    EXPECT_NEAR(patientZ(t2.document, t2.crosshair) - before, 10.0 * steps, 1e-9);
    EXPECT_LE(std::abs(patientZ(main, mainCrosshair) - patientZ(t2.document, t2.crosshair)),
              2.5 + 1e-9);  // the main volume's 5 mm slices: within half of one
    expectFollow("T2 scrolled");
  }
  // The linked cells' 3D cameras are the main one's (one Frame of Reference: no transform),
  // turned with it; the unlinked one keeps its own.
  EXPECT_DOUBLE_EQ(t2.render.params().camera.azimuthDeg, 30.0);
  mainRender.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 75.0; });
  EXPECT_NEAR(t2.render.params().camera.azimuthDeg, 75.0, 1e-9);
  EXPECT_NEAR(flair.render.params().camera.azimuthDeg, 75.0, 1e-9);
  EXPECT_NE(dwi.render.params().camera.azimuthDeg, 75.0);
  // Another Frame of Reference stays where it was (nothing maps it onto the others).
  EXPECT_DOUBLE_EQ(patientZ(dwi.document, dwi.crosshair), dwiZ);
}

}  // namespace
}  // namespace voxray
