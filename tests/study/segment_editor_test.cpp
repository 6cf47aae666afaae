// The segment editor's Qt-free parts (issue 34): the slice overlay of the segments and the
// threshold preview, paint strokes as one undo step, the edited box the 3D view uploads, the
// tools' recipes (the CLI's), the operations' buttons and the 3D mask choices.
#include <gtest/gtest.h>

#include "label_count.h"
#include "segment_overlay.h"
#include "segment_scissors.h"
#include "segment_tools.h"
#include "segmentation_model.h"
#include "slice_geometry.h"
#include "slice_image.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

const Volume& phantom64() {
  static const Volume v = makeHeadPhantom(64);  // 4 mm voxels, skull 1150 HU, soft tissue 40
  return v;
}

using test::countLabel;

// Voxel centres of slice k (axis 2) within R mm of the point C (voxel units): the disc's
// rasterisation, counted independently of segment_edit.
size_t discVoxels(const Volume& v, glm::dvec3 c, double r) {
  size_t n = 0;
  for (int j = 0; j < v.dims.y; ++j)
    for (int i = 0; i < v.dims.x; ++i) {
      const double dx = (i - c.x) * v.spacingMm.x, dy = (j - c.y) * v.spacingMm.y;
      n += dx * dx + dy * dy <= r * r;
    }
  return n;
}

TEST(SegmentOverlay, PaintedDiscIsFilledInItsColourAndOutlinedAtItsOpacity) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  const uint8_t l = m.addSegment("Lesion", {1.0f, 0.0f, 0.0f});
  m.setOpacity(l, 0.8f);
  const glm::dvec3 c(32, 32, 30);
  m.paintDisc(2, c, 10.0, l);
  // 10 mm on 4 mm voxels: the centres within 2.5 voxels, 21 of them.
  EXPECT_EQ(countLabel(m.segmentation(), l), discVoxels(v, c, 10.0));
  EXPECT_EQ(countLabel(m.segmentation(), l), 21u);

  const SliceAxes axes = sliceAxes(v.direction, Orientation::Axial);
  const PlaneGrid plane = slicePlane(v, axes, 30);
  const Image o = segmentOverlay(m.segmentation(), plane);
  ASSERT_EQ(o.width, plane.size.x);
  // The pixel over the disc's centre: the colour at 0.8 * kSegmentFillShare; the disc's edge
  // voxel (2 to the right on screen, whichever way the axis runs) at the whole 0.8.
  const glm::dvec2 centre = voxelToSlice(axes, v.dims, c);
  const double scale = plane.size.x / double(v.dims[axes.uAxis]);  // pixels per voxel
  const uint8_t* p = o.pixel(int(centre.x * scale), int(centre.y * scale));
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[1], 0);
  EXPECT_EQ(p[2], 0);
  EXPECT_EQ(p[3], uint8_t(std::lround(0.8 * kSegmentFillShare * 255)));
  const glm::dvec2 edge = voxelToSlice(axes, v.dims, c + glm::dvec3(2, 0, 0));
  EXPECT_EQ(o.pixel(int(edge.x * scale), int(edge.y * scale))[3], uint8_t(std::lround(0.8 * 255)));
  // Filled pixels: the 21 voxels' pixels (scale x scale each).
  size_t shown = 0;
  for (size_t i = 3; i < o.rgba.size(); i += 4) shown += o.rgba[i] != 0;
  EXPECT_EQ(shown, size_t(std::lround(21 * scale * scale)));
  // Another slice shows none of it, a hidden segment nothing.
  const Image other = segmentOverlay(m.segmentation(), slicePlane(v, axes, 31));
  for (size_t i = 3; i < other.rgba.size(); i += 4) ASSERT_EQ(other.rgba[i], 0);
  m.setVisible(l, false);
  const Image hidden = segmentOverlay(m.segmentation(), plane);
  for (size_t i = 3; i < hidden.rgba.size(); i += 4) ASSERT_EQ(hidden.rgba[i], 0);
}

TEST(SegmentOverlay, TurnedPlaneTakesEachPixelsVoxel) {
  const Volume& v = phantom64();
  // The axial plane through voxel z = 30 turned 90 degrees about the patient's x axis is the
  // coronal plane through the same centre: its pixels' voxels have y = 32 (the centre).
  const SliceAxes axes = sliceAxes(v.direction, Orientation::Axial);
  const glm::dmat3 turn(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  const PlaneGrid g = viewPlane(v, axes, {32, 32, 30}, turn);
  const auto voxels = planeVoxels(gridOf(v), g);
  size_t inside = 0;
  for (int64_t i : voxels) {
    if (i < 0) continue;
    ++inside;
    const int64_t plane = int64_t(v.dims.x) * v.dims.y;
    ASSERT_EQ((i % plane) / v.dims.x, 32) << "pixel off the turned plane";
  }
  EXPECT_GT(inside, size_t(v.dims.x * v.dims.z / 2));
}

TEST(SegmentTools, ThresholdPreviewCountIsTheMasksVoxelsInTheSlice) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  SegmentToolSettings s;
  s.label = m.addSegment("Bone", {1, 1, 0.8f});
  s.range = {700, 3000};
  const size_t preview = previewCount(v, 2, 30, s.range);
  applyThreshold(m, v, s);
  size_t inSlice = 0;
  for (int y = 0; y < v.dims.y; ++y)
    for (int x = 0; x < v.dims.x; ++x)
      inSlice += m.segmentation().labels[v.index(x, y, 30)] == s.label;
  EXPECT_GT(preview, 50u);  // the skull's ring
  EXPECT_EQ(preview, inSlice);
  // The overlay of the preview colours exactly the preview's voxels (one pixel per voxel on
  // the axial plane's square 4 mm pixels).
  const PlaneGrid plane = slicePlane(v, sliceAxes(v.direction, Orientation::Axial), 30);
  ASSERT_EQ(plane.size, glm::ivec2(64, 64));
  const Image o = thresholdOverlay(v, plane, s.range, {1, 1, 0});
  size_t coloured = 0;
  for (size_t i = 3; i < o.rgba.size(); i += 4) coloured += o.rgba[i] != 0;
  EXPECT_EQ(coloured, preview);
  EXPECT_EQ(m.undoText(), "Undo Threshold");
}

TEST(SegmentTools, SeedClickGivesTheCliRecipesLabelMap) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  SegmentToolSettings s;
  s.label = m.addSegment("Segment", {0.9f, 0.85f, 0.7f});
  s.range = {700, 3000};
  s.connectivity = Connectivity::Full26;
  // A skull voxel: on the x axis through the centre, in the shell 64 ... 70.4 mm out.
  glm::ivec3 seed(-1);
  for (int x = 63; x > 32 && seed.x < 0; --x)
    if (v.toPhysical(v.at(x, 31, 32)) >= 700) seed = {x, 31, 32};
  ASSERT_GE(seed.x, 0);
  seedClick(m, v, s, seed);
  // voxray-cli segment --threshold 700,3000 --seed I:J:K --connectivity 26 runs this.
  SegmentRecipe r = seedRecipe(s.range, seed, s.connectivity);
  const Segmentation cli = segmentationFromRecipe(v, r);
  EXPECT_EQ(m.segmentation().labels, cli.labels);
  EXPECT_GT(countLabel(cli, 1), 1000u);
  // A seed outside the range says so and changes nothing.
  s.range = {2000, 3000};
  const auto before = m.segmentation().labels;
  EXPECT_THROW(seedClick(m, v, s, seed), Error);
  EXPECT_EQ(m.segmentation().labels, before);
}

TEST(SegmentationModel, AStrokeOfDabsIsOneUndoStep) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  const uint8_t l = m.addSegment("Paint", {0, 1, 0});
  m.paintDisc(2, {20, 20, 30}, 6.0, l);  // before the stroke: its own step
  const auto beforeStroke = m.segmentation().labels;
  (void)m.takeEdits();
  m.beginStroke();
  for (int x = 18; x <= 40; x += 2) m.paintDisc(2, {double(x), 24, 30}, 6.0, l);
  m.endStroke();
  const auto afterStroke = m.segmentation().labels;
  // The edited box holds every voxel the stroke changed (the 3D view uploads only it).
  const auto edits = m.takeEdits();
  ASSERT_TRUE(edits.any);
  EXPECT_FALSE(edits.whole);
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        const size_t i = v.index(x, y, z);
        if (beforeStroke[i] == afterStroke[i]) continue;
        ASSERT_TRUE(x >= edits.lo.x && x < edits.hi.x && y >= edits.lo.y && y < edits.hi.y &&
                    z >= edits.lo.z && z < edits.hi.z);
      }
  EXPECT_EQ(m.undoText(), "Undo Paint");
  m.undo();  // the whole stroke
  EXPECT_EQ(m.segmentation().labels, beforeStroke);
  EXPECT_EQ(m.undoText(), "Undo Paint");  // the disc before the stroke
  m.redo();
  EXPECT_EQ(m.segmentation().labels, afterStroke);
  m.undo();
  m.undo();
  EXPECT_EQ(countLabel(m.segmentation(), l), 0u);
  // A new map is sent whole.
  m.reset(v);
  EXPECT_TRUE(m.takeEdits().whole);
}

TEST(SegmentTools, OperationsAreOneUndoStepEach) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  SegmentToolSettings s;
  s.label = m.addSegment("Shell", {1, 1, 1});
  // A hollow ball: 20 mm painted, the inner 10 mm erased; fill holes makes it whole.
  m.paintSphere({32, 32, 32}, 20.0, s.label);
  const size_t ball = countLabel(m.segmentation(), s.label);
  m.eraseSphere({32, 32, 32}, 10.0, s.label);
  const size_t shell = countLabel(m.segmentation(), s.label);
  ASSERT_LT(shell, ball);
  applyOperation(m, s.label, MaskOperation::FillHoles, 0, Connectivity::Faces6);
  EXPECT_EQ(countLabel(m.segmentation(), s.label), ball);
  EXPECT_EQ(m.undoText(), "Undo Fill holes");
  m.undo();
  EXPECT_EQ(countLabel(m.segmentation(), s.label), shell);
  // A 4 mm margin (one voxel) grows the shell outwards and inwards.
  applyOperation(m, s.label, MaskOperation::Margin, 4.0, Connectivity::Faces6);
  EXPECT_GT(countLabel(m.segmentation(), s.label), shell);
  EXPECT_EQ(m.undoText(), "Undo Margin");
  // Add moves the other segment's voxels into the target.
  const uint8_t other = m.addSegment("Blob", {0, 1, 0});
  m.paintSphere({12, 32, 32}, 8.0, other);
  const size_t blob = countLabel(m.segmentation(), other);
  const size_t grown = countLabel(m.segmentation(), s.label);
  applyLogical(m, s.label, other, LogicalOp::Add);
  EXPECT_EQ(countLabel(m.segmentation(), other), 0u);
  EXPECT_EQ(countLabel(m.segmentation(), s.label), grown + blob);
  EXPECT_THROW(applyOperation(m, 77, MaskOperation::FillHoles, 0, Connectivity::Faces6), Error);
}

TEST(SegmentScissors, APolygonRemovesWhatLiesBehindItAndOnlyThat) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  const uint8_t l = m.addSegment("Ball", {1, 1, 1});
  m.paintSphere({32, 32, 32}, 40.0, l);
  const Segmentation before = m.segmentation();
  RenderParams p;
  p.width = 200;
  p.height = 150;
  p.camera.azimuthDeg = 30.0;
  const ViewProjection proj = makeViewProjection(v, p, {200.0, 150.0});
  // The screen's left half.
  const std::vector<glm::dvec2> polygon = {{0, 0}, {100, 0}, {100, 150}, {0, 150}};
  applyScissors(m, v, proj, polygon, l);
  EXPECT_EQ(m.undoText(), "Undo Scissors");
  size_t removed = 0, kept = 0;
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        const size_t i = v.index(x, y, z);
        if (before.labels[i] != l) {
          ASSERT_EQ(m.segmentation().labels[i], before.labels[i]);
          continue;
        }
        const auto at = proj.project(voxelToWorldMm(v, glm::dvec3(x, y, z)));
        ASSERT_TRUE(at);
        const bool cut = m.segmentation().labels[i] != l;
        ASSERT_EQ(cut, at->x < 100.0) << "voxel " << x << "," << y << "," << z;
        (cut ? removed : kept) += 1;
      }
  // The ball's centre projects to the screen's centre: about half on each side.
  EXPECT_GT(removed, countLabel(before, l) / 3);
  EXPECT_GT(kept, countLabel(before, l) / 3);
  m.undo();
  EXPECT_EQ(m.segmentation().labels, before.labels);
  // A pick at the ball's edge, half a voxel outside it, still names it; far off, nothing.
  EXPECT_EQ(segmentAt(m.segmentation(), {32, 32, 32}), l);
  EXPECT_EQ(segmentAt(m.segmentation(), {32 + 10.5, 32, 32}), l);  // 40 mm = 10 voxels
  EXPECT_EQ(segmentAt(m.segmentation(), {32 + 13, 32, 32}), 0);
  EXPECT_FALSE(insidePolygon({{0, 0}, {1, 1}}, {0.5, 0.5}));  // no area
}

TEST(SegmentScissors, KeepModeKeepsOnlyWhatLiesBehindThePolygon) {
  const Volume& v = phantom64();
  SegmentationModel m;
  m.reset(v);
  const uint8_t l = m.addSegment("Ball", {1, 1, 1});
  m.paintSphere({32, 32, 32}, 40.0, l);
  const Segmentation before = m.segmentation();
  RenderParams p;
  p.width = 200;
  p.height = 150;
  p.camera.azimuthDeg = 30.0;
  const ViewProjection proj = makeViewProjection(v, p, {200.0, 150.0});
  const std::vector<glm::dvec2> polygon = {{0, 0}, {100, 0}, {100, 150}, {0, 150}};
  // Remove and Keep split the segment's voxels in two: what one keeps the other removes.
  const Mask removeKeeps = scissorsKeep(before, v, proj, polygon, l, ScissorsMode::Remove);
  applyScissors(m, v, proj, polygon, l, ScissorsMode::Keep);
  EXPECT_EQ(m.undoText(), "Undo Scissors keep");
  size_t kept = 0, total = 0;
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        const size_t i = v.index(x, y, z);
        if (before.labels[i] != l) {
          ASSERT_EQ(m.segmentation().labels[i], before.labels[i]);
          continue;
        }
        ++total;
        const auto at = proj.project(voxelToWorldMm(v, glm::dvec3(x, y, z)));
        ASSERT_TRUE(at);
        const bool stays = m.segmentation().labels[i] == l;
        ASSERT_EQ(stays, at->x < 100.0) << "voxel " << x << "," << y << "," << z;
        ASSERT_NE(stays, removeKeeps[i] != 0) << "voxel " << x << "," << y << "," << z;
        kept += stays;
      }
  EXPECT_EQ(countLabel(m.segmentation(), l), kept);
  EXPECT_GT(kept, total / 3);  // the centre projects to the screen's centre
  EXPECT_LT(kept, total * 2 / 3);
  // A lasso of no area keeps nothing; undo brings every voxel back.
  applyScissors(m, v, proj, {{0, 0}, {1, 1}}, l, ScissorsMode::Keep);
  EXPECT_EQ(countLabel(m.segmentation(), l), 0u);
  m.undo();
  m.undo();
  EXPECT_EQ(m.segmentation().labels, before.labels);
}

TEST(SegmentTools, RangeFromTheTransferFunctionIsItsOpaqueHuRange) {
  const HuRange values{-1024, 3071};
  RenderParams p;
  p.mode = Mode::Dvr;
  const glm::dvec3 c(1.0);
  p.transferFunction = {{-1000, glm::dvec4(c, 0)},  {150, glm::dvec4(c, 0)},
                        {300, glm::dvec4(c, 0.4)},  {500, glm::dvec4(c, 0)},
                        {1200, glm::dvec4(c, 0.8)}, {2000, glm::dvec4(c, 0)},
                        {3000, glm::dvec4(c, 0)}};
  // Opacity > 0 from just above 150 HU (the ramp's foot) to just below 2000 HU; the gap at
  // 500 HU lies between and stays in.
  HuRange r = rangeFromTransferFunction(p, values);
  EXPECT_DOUBLE_EQ(r.lo, 150);
  EXPECT_DOUBLE_EQ(r.hi, 2000);
  p.presetShiftHu = 100;  // the shift moves the custom table too
  r = rangeFromTransferFunction(p, values);
  EXPECT_DOUBLE_EQ(r.lo, 250);
  EXPECT_DOUBLE_EQ(r.hi, 2100);
  // Opaque at the table's top end: constant beyond it, up to the volume's highest value.
  p.presetShiftHu = 0;
  p.transferFunction = {{-1000, glm::dvec4(c, 0)}, {200, glm::dvec4(c, 0.5)}};
  r = rangeFromTransferFunction(p, values);
  EXPECT_DOUBLE_EQ(r.lo, -1000);
  EXPECT_DOUBLE_EQ(r.hi, 3071);
  // iso: the surface's range, clamped to the volume's values.
  p.mode = Mode::Iso;
  p.isoLo = 400;
  p.isoHi = 32767;
  r = rangeFromTransferFunction(p, values);
  EXPECT_DOUBLE_EQ(r.lo, 400);
  EXPECT_DOUBLE_EQ(r.hi, 3071);
  p.mode = Mode::Dvr;
  p.transferFunction = {{-1000, glm::dvec4(c, 0)}, {3000, glm::dvec4(c, 0)}};
  EXPECT_THROW(rangeFromTransferFunction(p, values), Error);

  // The threshold from a table opaque around the phantom's skull (1150 HU) takes the skull's
  // voxels, counted here independently of segment_mask.
  const Volume& v = phantom64();
  p.transferFunction = {
      {900, glm::dvec4(c, 0)}, {1100, glm::dvec4(c, 0.6)}, {1400, glm::dvec4(c, 0)}};
  SegmentationModel m;
  m.reset(v);
  SegmentToolSettings s;
  s.label = m.addSegment("Skull", {1, 1, 1});
  s.range = rangeFromTransferFunction(p, values);
  applyThreshold(m, v, s);
  size_t expected = 0;
  for (int16_t stored : v.voxels) {
    const double hu = v.toPhysical(stored);
    expected += hu >= 900 && hu <= 1400;
  }
  EXPECT_GT(expected, 500u);  // the skull shell of the 64³ phantom: 614 voxels
  EXPECT_EQ(countLabel(m.segmentation(), s.label), expected);
}

TEST(SegmentTools, MaskChoicesShowOrHideAndExcludeEachOther) {
  SegmentMask m;
  m = withMaskChoice(m, 3, MaskChoice::ShowOnly);
  m = withMaskChoice(m, 1, MaskChoice::ShowOnly);
  EXPECT_EQ(toString(m), "show:1,3");
  EXPECT_EQ(maskChoiceOf(m, 3), MaskChoice::ShowOnly);
  EXPECT_EQ(maskChoiceOf(m, 2), MaskChoice::Off);
  m = withMaskChoice(m, 2, MaskChoice::Hide);  // Hide drops the Show choices
  EXPECT_EQ(toString(m), "hide:2");
  m = withMaskChoice(m, 2, MaskChoice::Off);
  EXPECT_EQ(m.kind, SegmentMask::Kind::Off);
  const HuRange r = rangeFromWindow({2000, 500});
  EXPECT_DOUBLE_EQ(r.lo, -500);
  EXPECT_DOUBLE_EQ(r.hi, 1500);
}

}  // namespace
}  // namespace voxray
