// Per-segment transfer functions (issue 35, RenderParams::segmentTfs, SEGMENT_TF): a segment's
// own 1D table classifies the samples whose nearest voxel holds its label; the others keep the
// volume's table. The scene is labels_test's: test_volumes.h's anisotropic ball (1000 HU,
// radius 13 voxels, 1 x 1.1 x 1.6 mm) and label 1 on the voxels within test::kSphereSegmentRadiusMm
// of its centre.
//
// Geometry of the checks, as labels_test: a sample takes the label of its nearest voxel, within
// half a voxel's diagonal (1.09 mm) of it. A ray that passes the centre farther than
// test::kSphereSegmentRadiusMm + 1.09 mm reads no label 1; one nearer than
// test::kSphereSegmentRadiusMm - 1.09 mm crosses label-1 voxels. Pixels between the two are not
// checked.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ball_scene.h"
#include "segment_tf.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/camera.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/error.h"
#include "voxray/io/segmentation.h"

namespace voxray {

namespace {

// Label 1 within test::kSphereSegmentRadiusMm of the centre; its segment green, so that a red pixel
// can only come from its own table (which replaces the tint).
Segmentation greenSphereSegment(const Volume& v) {
  return test::sphereSegment(v, {0.0f, 1.0f, 0.0f});
}

const std::vector<ControlPoint> kTransparent = {{-1000.0, {1.0, 1.0, 1.0, 0.0}},
                                                {3000.0, {1.0, 1.0, 1.0, 0.0}}};
const std::vector<ControlPoint> kRedOpaque = {{-1000.0, {1.0, 0.0, 0.0, 1.0}},
                                              {3000.0, {1.0, 0.0, 0.0, 1.0}}};

// The volume transparent, segment 1 red and opaque at every value.
RenderParams redBallParams(bool shading) {
  RenderParams p = test::faintTableParams(shading);
  p.transferFunction = kTransparent;
  p.segmentTfs[1] = kRedOpaque;
  return p;
}

// The faint white table on the volume, segment 1 a faint red ramp over the ball's HU: both
// tables show, and the inside matters.
RenderParams mixedParams(bool shading) {
  RenderParams p = test::faintTableParams(shading);
  p.segmentTfs[1] = {{-1000.0, {1.0, 0.2, 0.1, 0.0}},
                     {0.0, {1.0, 0.2, 0.1, 0.02}},
                     {1000.0, {0.9, 0.4, 0.1, 0.08}}};
  return p;
}

Image renderWithSegmentTf(const Volume& v, const RenderParams& p, const Segmentation& seg,
                          bool packets, bool ess = true, FrameStats* stats = nullptr,
                          VolumeStorage storage = VolumeStorage::Buffer) {
  Raycaster rc(test::pocl(), v, storage);
  RaycasterOptions o;
  o.packets = packets;
  o.emptySpaceSkipping = ess;
  o.countSamples = stats != nullptr;
  rc.setOptions(o);
  rc.setSegmentation(seg);
  Image img;
  rc.render(p, img, stats);
  return img;
}

}  // namespace

TEST(SegmentTf, ARedOpaqueSegmentShowsRedAndTheTransparentRestBackground) {
  const Volume& v = test::anisotropicBall();
  const Segmentation seg = greenSphereSegment(v);
  const RenderParams p = redBallParams(false);
  const std::vector<double> dist = test::sphereRayDistances(v, p);
  int insideCount = 0, outsideCount = 0;
  for (double d : dist)
    insideCount += test::crossesSphereSegment(d), outsideCount += test::missesSphereSegment(d);
  ASSERT_EQ(insideCount, 112);  // labels_test's inner disc of 64 x 48 pixels
  ASSERT_GT(outsideCount, 1500);
  for (bool packets : {true, false})
    for (bool ess : {true, false}) {
      SCOPED_TRACE(std::string(packets ? "packets" : "per ray") + (ess ? " ess" : " no ess"));
      const Image img = renderWithSegmentTf(v, p, seg, packets, ess);
      int red = 0, black = 0, redInside = 0, blackOutside = 0;
      for (size_t i = 0; i < dist.size(); ++i) {
        const int r = img.rgba[4 * i], g = img.rgba[4 * i + 1], b = img.rgba[4 * i + 2];
        // Opacity 1 per step is 1 after the step correction: the first labelled sample is the
        // whole pixel, exactly red; nothing else shows (the volume's table is transparent).
        const bool isRed = r == 255 && g == 0 && b == 0, isBlack = r == 0 && g == 0 && b == 0;
        red += isRed, black += isBlack;
        if (test::crossesSphereSegment(dist[i])) redInside += isRed;
        if (test::missesSphereSegment(dist[i])) blackOutside += isBlack;
        EXPECT_TRUE(isRed || isBlack) << "pixel " << i << ": " << r << "," << g << "," << b;
      }
      EXPECT_EQ(redInside, insideCount);
      EXPECT_EQ(blackOutside, outsideCount);
      EXPECT_EQ(red + black, int(dist.size()));
      // The disc's edge pixels (between the two bounds) go either way, so only bounds.
      EXPECT_GE(red, insideCount);
      EXPECT_LE(red, int(dist.size()) - outsideCount);
    }
}

TEST(SegmentTf, KernelsMatchTheReference) {
  const Volume& v = test::anisotropicBall();
  const Segmentation seg = greenSphereSegment(v);
  for (const char* scene : {"red", "mixed"})
    for (bool shading : {true, false}) {
      RenderParams p = std::string(scene) == "red" ? redBallParams(shading) : mixedParams(shading);
      for (const char* mask : {"off", "hide:1"}) {
        p.segmentMask = parseSegmentMask(mask);
        const Image ref = renderReference(v, p, seg);
        for (bool packets : {true, false}) {
          const std::string what = std::string(scene) + " " + mask +
                                   (shading ? " shaded" : " unshaded") +
                                   (packets ? " packets" : " per ray");
          test::expectCloseToReference(renderWithSegmentTf(v, p, seg, packets), ref, what);
        }
        // The volume as an image (GPUs' storage), the labels and tables still buffers.
        if (test::pocl().device().imageSupport)
          test::expectCloseToReference(
              renderWithSegmentTf(v, p, seg, false, true, nullptr, VolumeStorage::Image3d), ref,
              std::string(scene) + " " + mask + " image3d");
      }
    }
  // The red scene unshaded, hidden: nothing at all shows.
  RenderParams hidden = redBallParams(false);
  hidden.segmentMask = parseSegmentMask("hide:1");
  const Image none = renderReference(v, hidden, seg);
  for (size_t i = 0; i < none.rgba.size(); i += 4) ASSERT_EQ(none.rgba[i], 0) << i;
}

TEST(SegmentTf, SkippingIsExactAndStillLeaps) {
  const Volume& v = test::anisotropicBall();
  const Segmentation seg = greenSphereSegment(v);
  for (bool shading : {true, false})
    for (bool packets : {true, false}) {
      SCOPED_TRACE(std::string(shading ? "shaded" : "unshaded") + (packets ? " packets" : ""));
      for (const RenderParams& p : {redBallParams(shading), mixedParams(shading)})
        EXPECT_EQ(test::maxDiff(renderWithSegmentTf(v, p, seg, packets, true),
                                renderWithSegmentTf(v, p, seg, packets, false)),
                  0);
    }
  // The transparent volume is leapt outside the cells that hold label 1: far fewer samples
  // than without skipping (and the opaque red stops each ray at its first labelled sample).
  FrameStats skipped, all;
  renderWithSegmentTf(v, redBallParams(true), seg, true, true, &skipped);
  renderWithSegmentTf(v, redBallParams(true), seg, true, false, &all);
  EXPECT_LT(skipped.samples, 0.5 * all.samples) << skipped.samples << " of " << all.samples;
}

TEST(SegmentTf, OnlyFramesWithAnOwnTableCompileIt) {
  const Volume& v = test::anisotropicBall();
  const Segmentation seg = greenSphereSegment(v);
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  rc.setSegmentation(seg);
  RenderParams p = test::faintTableParams();
  EXPECT_NE(rc.variantOptions(p).find("SEGMENT_TF=0"), std::string::npos);
  p.segmentTfs[1] = kRedOpaque;
  EXPECT_NE(rc.variantOptions(p).find("SEGMENT_TF=1"), std::string::npos);
  // A table for a label no segment names, or an invisible segment's: none.
  RenderParams other = test::faintTableParams();
  other.segmentTfs[2] = kRedOpaque;
  EXPECT_NE(rc.variantOptions(other).find("SEGMENT_TF=0"), std::string::npos);
  Segmentation hidden = seg;
  hidden.segments[0].visible = false;
  rc.setSegmentation(hidden);
  EXPECT_NE(rc.variantOptions(p).find("SEGMENT_TF=0"), std::string::npos);
  // A 2D transfer function keeps its own table everywhere.
  rc.setSegmentation(seg);
  RenderParams with2d = p;
  with2d.tf2d = parseTf2d("rect:0,2000,0,1000,1,1,1,0.5");
  EXPECT_NE(rc.variantOptions(with2d).find("SEGMENT_TF=0"), std::string::npos);
  // Without the table the pixels are labels_test's (the tint back).
  RenderParams plain = test::faintTableParams();
  EXPECT_EQ(rc.render(plain).rgba, renderWithSegmentTf(v, plain, seg, true).rgba);
  EXPECT_NE(rc.render(p).rgba, rc.render(plain).rgba);
}

TEST(SegmentTf, TextReadsAndWritesBack) {
  RenderParams p;
  fromText(p, "segment-tf=2:-1000:1:0:0:0,500:1:0:0:1;1:CT-Bone\n");
  ASSERT_EQ(p.segmentTfs.size(), 2u);
  EXPECT_EQ(p.segmentTfs.at(2).size(), 2u);
  EXPECT_DOUBLE_EQ(p.segmentTfs.at(2)[1].rgba.a, 1.0);
  EXPECT_EQ(p.segmentTfs.at(1), findPreset("CT-Bone").tf.points);
  RenderParams back;
  fromText(back, toText(p));
  EXPECT_EQ(back.segmentTfs, p.segmentTfs);
  EXPECT_EQ(formatSegmentTfs(back.segmentTfs), formatSegmentTfs(p.segmentTfs));
  fromText(p, "segment-tf=off\n");
  EXPECT_TRUE(p.segmentTfs.empty());
  for (const char* bad : {"1", "0:CT-Bone", "256:CT-Bone", "x:CT-Bone", "1:CT-Bone;1:CT-Skin",
                          "1:no-such-preset", "1:-1000:1:0:0", "1:missing.json", "1:CT-Bone;"}) {
    try {
      parseSegmentTfs(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::Input) << bad;
    }
  }
}

}  // namespace voxray
