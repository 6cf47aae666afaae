// Label-aware dvr (issue 34): Raycaster::setSegmentation, segment-mask and segment-blend.
// The scene: test_volumes.h's ball (1000 HU, radius 13 voxels, anisotropic 1 x 1.1 x 1.6 mm)
// under a faint white table, so that the inside shows, and a segment (label 1) that is a
// sphere of test::kSphereSegmentRadiusMm around the volume's centre, where the camera looks.
//
// Geometry of the checks: a sample takes the label of its nearest voxel, which lies within
// half a voxel's diagonal (1.09 mm here) of it. So a ray that passes the centre farther than
// test::kSphereSegmentRadiusMm + 1.09 mm reads no label 1, and one nearer than
// test::kSphereSegmentRadiusMm - 1.09 mm crosses label-1 voxels over several steps. Pixels between
// the two are not checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ball_scene.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/camera.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/error.h"
#include "voxray/io/segmentation.h"

namespace voxray {

namespace {

// The float kernels against the double reference (ball_scene.h); a sample within rounding of
// a voxel's middle may also take the neighbour's label there, as those bounds allow.
using test::expectCloseToReference;

// Label 1 on the voxels within test::kSphereSegmentRadiusMm of the volume's centre; one red
// segment.
Segmentation redSphereSegment(const Volume& v) {
  return test::sphereSegment(v, {1.0f, 0.0f, 0.0f});
}

Image renderWithLabels(const Volume& v, const RenderParams& p, const Segmentation* seg,
                       bool packets, bool ess = true, FrameStats* stats = nullptr,
                       VolumeStorage storage = VolumeStorage::Buffer) {
  Raycaster rc(test::pocl(), v, storage);
  RaycasterOptions o;
  o.packets = packets;
  o.emptySpaceSkipping = ess;
  o.countSamples = stats != nullptr;
  rc.setOptions(o);
  if (seg) rc.setSegmentation(*seg);
  Image img;
  rc.render(p, img, stats);
  return img;
}

}  // namespace

TEST(Labels, ASegmentationThatChangesNothingRendersThePixelsWithout) {
  const Volume& v = test::anisotropicBall();
  const RenderParams p = test::faintTableParams();
  Segmentation none = redSphereSegment(v);
  none.segments.clear();  // labels, but no segment names them
  Segmentation hidden = redSphereSegment(v);
  hidden.segments[0].visible = false;
  RenderParams blend0 = p;
  blend0.segmentBlend = 0.0;
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image plain = renderWithLabels(v, p, nullptr, packets);
    EXPECT_EQ(renderWithLabels(v, p, &none, packets).rgba, plain.rgba);
    EXPECT_EQ(renderWithLabels(v, p, &hidden, packets).rgba, plain.rgba);
    const Segmentation red = redSphereSegment(v);
    EXPECT_EQ(renderWithLabels(v, blend0, &red, packets).rgba, plain.rgba);
    Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
    RaycasterOptions o;
    o.packets = packets;
    rc.setOptions(o);
    rc.setSegmentation(none);
    EXPECT_NE(rc.variantOptions(p).find("LABELS=0"), std::string::npos);
    rc.setSegmentation(red);
    EXPECT_NE(rc.variantOptions(p).find("LABELS=1"), std::string::npos);
    // Adaptive steps read the colour table's levels alone: off while labels show.
    RenderParams adaptive = p;
    adaptive.adaptiveError = 0.01;
    EXPECT_NE(rc.variantOptions(adaptive).find("ADAPTIVE=0"), std::string::npos);
    EXPECT_NE(rc.render(p).rgba, plain.rgba);
    rc.clearSegmentation();
    EXPECT_EQ(rc.render(p).rgba, plain.rgba);
    // Not dvr: no labels.
    RenderParams mip = p;
    mip.mode = Mode::Mip;
    rc.setSegmentation(red);
    EXPECT_NE(rc.variantOptions(mip).find("LABELS=0"), std::string::npos);
  }
}

TEST(Labels, KernelsMatchTheReference) {
  const Volume& v = test::anisotropicBall();
  const Segmentation seg = redSphereSegment(v);
  for (const char* mask : {"off", "show:1", "hide:1"})
    for (bool shading : {true, false}) {
      RenderParams p = test::faintTableParams(shading);
      p.segmentMask = parseSegmentMask(mask);
      p.segmentBlend = 0.8;
      const Image ref = renderReference(v, p, seg);
      for (bool packets : {true, false}) {
        const std::string what = std::string(mask) + (shading ? " shaded" : " unshaded") +
                                 (packets ? " packets" : " per ray");
        expectCloseToReference(renderWithLabels(v, p, &seg, packets), ref, what);
      }
      // The volume as an image (GPUs), the labels still a buffer beside it.
      if (test::pocl().device().imageSupport)
        expectCloseToReference(
            renderWithLabels(v, p, &seg, false, true, nullptr, VolumeStorage::Image3d), ref,
            std::string(mask) + " image3d");
    }
}

TEST(Labels, ARedSphereSegmentShowsRedWhereItLies) {
  const Volume& v = test::anisotropicBall();
  const RenderParams p = test::faintTableParams();
  const Segmentation seg = redSphereSegment(v);
  const std::vector<double> dist = test::sphereRayDistances(v, p);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image plain = renderWithLabels(v, p, nullptr, packets);
    const Image img = renderWithLabels(v, p, &seg, packets);
    int red = 0, outsideCount = 0;
    for (size_t i = 0; i < dist.size(); ++i) {
      const int r = img.rgba[4 * i], g = img.rgba[4 * i + 1], b = img.rgba[4 * i + 2];
      if (test::crossesSphereSegment(dist[i])) {
        // The red chord is 2 sqrt(6^2 - d^2) mm of the ray's 20-26 mm in the ball: 6.9 mm at
        // the disc's edge, where red leads green by 25 levels (seen: 25 ... 55), over 9.6 mm
        // within 3 mm of the middle (seen: 43 ... 55). Green is what the red replaced.
        EXPECT_GT(r, g + (dist[i] < 3.0 ? 35 : 15)) << "pixel " << i;
        EXPECT_LT(g + 20, int(plain.rgba[4 * i + 1])) << "pixel " << i;
        EXPECT_EQ(g, b) << "pixel " << i;
        red += r > g + 15;
      } else if (test::missesSphereSegment(dist[i])) {
        // The white table: grey, and exactly the pixels without labels.
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgba[4 * i + c], plain.rgba[4 * i + c]);
        ++outsideCount;
      }
    }
    EXPECT_EQ(red, 112);  // every pixel of the inner disc (112 of 64 x 48)
    EXPECT_GT(outsideCount, 1500);
  }
}

TEST(Labels, AShowMaskRendersNothingOutsideTheSegmentsDisc) {
  const Volume& v = test::anisotropicBall();
  RenderParams p = test::faintTableParams();
  p.segmentMask = parseSegmentMask("show:1");
  const Segmentation seg = redSphereSegment(v);
  const std::vector<double> dist = test::sphereRayDistances(v, p);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image img = renderWithLabels(v, p, &seg, packets);
    int shown = 0;
    for (size_t i = 0; i < dist.size(); ++i) {
      const int r = img.rgba[4 * i];
      if (test::missesSphereSegment(dist[i]))
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgba[4 * i + c], 0) << "pixel " << i;
      if (test::crossesSphereSegment(dist[i])) {
        EXPECT_GT(r, 40) << "pixel " << i;
        shown += r > 40;
      }
    }
    EXPECT_GT(shown, 40);
  }
}

TEST(Labels, AHideMaskRemovesTheSegment) {
  const Volume& v = test::anisotropicBall();
  RenderParams p = test::faintTableParams();
  p.segmentMask = parseSegmentMask("hide:1");
  const Segmentation seg = redSphereSegment(v);
  const std::vector<double> dist = test::sphereRayDistances(v, p);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image plain = renderWithLabels(v, p, nullptr, packets);
    const Image img = renderWithLabels(v, p, &seg, packets);
    int darker = 0;
    for (size_t i = 0; i < dist.size(); ++i) {
      const int r = img.rgba[4 * i], g = img.rgba[4 * i + 1];
      EXPECT_EQ(r, g) << "pixel " << i;  // no red anywhere: the table is white
      if (test::missesSphereSegment(dist[i]))
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgba[4 * i + c], plain.rgba[4 * i + c]);
      // The middle of the ball is gone along these rays: less white gathered.
      if (test::crossesSphereSegment(dist[i])) darker += r + 10 < plain.rgba[4 * i];
    }
    EXPECT_GT(darker, 40);
  }
}

TEST(Labels, SkippingStaysExactWithAMaskAndLeapsWhatItHides) {
  const Volume& v = test::anisotropicBall();
  const Segmentation seg = redSphereSegment(v);
  for (const char* mask : {"off", "show:1", "hide:1"})
    for (bool packets : {true, false}) {
      SCOPED_TRACE(std::string(mask) + (packets ? " packets" : " per ray"));
      RenderParams p = test::faintTableParams();
      p.segmentMask = parseSegmentMask(mask);
      EXPECT_EQ(test::maxDiff(renderWithLabels(v, p, &seg, packets, true),
                              renderWithLabels(v, p, &seg, packets, false)),
                0);
    }
  // A show mask leaps the macro cells without label 1: far fewer samples than without it.
  RenderParams p = test::faintTableParams();
  FrameStats all, shown;
  renderWithLabels(v, p, &seg, true, true, &all);
  p.segmentMask = parseSegmentMask("show:1");
  renderWithLabels(v, p, &seg, true, true, &shown);
  EXPECT_LT(shown.samples, 0.5 * all.samples) << shown.samples << " of " << all.samples;
}

TEST(Labels, AnEditedBoxRendersAsTheWholeMapSetAgain) {
  const Volume& v = test::anisotropicBall();
  const Segmentation full = redSphereSegment(v);
  Segmentation edited = full;
  std::fill(edited.labels.begin(), edited.labels.end(), uint8_t(0));
  for (const char* mask : {"off", "show:1"}) {
    SCOPED_TRACE(mask);
    RenderParams p = test::faintTableParams();
    p.segmentMask = parseSegmentMask(mask);
    Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
    rc.setSegmentation(edited);
    rc.render(p);  // classified without the sphere
    // The sphere "painted": its voxels lie within 6 / (1, 1.1, 1.6) voxels of the centre.
    rc.updateSegmentation(full, {13, 11, 7}, {26, 24, 16});
    EXPECT_EQ(rc.render(p).rgba, renderWithLabels(v, p, &full, true).rgba);
  }
}

TEST(Labels, ASegmentationOffTheVolumesGridIsRefused) {
  const Volume& v = test::anisotropicBall();
  Segmentation s = redSphereSegment(v);
  s.grid.spacingMm.z = 2.0;
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  try {
    rc.setSegmentation(s);
    FAIL() << "a label map on other voxels was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_NE(std::string(e.what()).find("volume's voxels"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(rc.hasSegmentation());
}

TEST(Labels, SegmentMaskTextReadsAndWritesBack) {
  SegmentMask m = parseSegmentMask("show:3,1,3");
  EXPECT_EQ(m.kind, SegmentMask::Kind::Show);
  EXPECT_EQ(m.labels, (std::vector<int>{1, 3}));
  EXPECT_EQ(toString(m), "show:1,3");
  EXPECT_EQ(toString(parseSegmentMask("hide:255")), "hide:255");
  EXPECT_EQ(parseSegmentMask("off").kind, SegmentMask::Kind::Off);
  for (const char* bad :
       {"show", "show:", "show:0", "hide:256", "hide:1,,2", "hide:1,", "paint:1", "show:x"})
    EXPECT_THROW(parseSegmentMask(bad), Error) << bad;
  RenderParams p;
  fromText(p, "segment-mask=hide:2,7\nsegment-blend=0.25\n");
  EXPECT_EQ(toString(p.segmentMask), "hide:2,7");
  EXPECT_DOUBLE_EQ(p.segmentBlend, 0.25);
  EXPECT_THROW(fromText(p, "segment-blend=1.5\n"), Error);
}

}  // namespace voxray
