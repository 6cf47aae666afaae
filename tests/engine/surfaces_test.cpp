// Segments shown as smooth surfaces (issue 34, Raycaster's surface pass): a voxelised sphere of
// radius 15 mm (1 mm voxels, voxel centres within 15 mm) drawn over an empty dvr (the table
// transparent everywhere), so that every pixel the frame colours is the surface's.
//   silhouette: the covered pixels' area as a disc's radius, against 15 mm / the pixel's size;
//   normals: the shading normal of each hit pixel against the analytic sphere's at the hit
//   point, for the smoothed field (sigma 1.25 voxels, the default) and the blocky label surface
//   (sigma 0: the mask itself, trilinear), median and 95th percentile; colours: two spheres, red
//   and green, each at its own pixels; a hidden one draws nothing; depth: a surface inside an
//   opaque dvr ball is not seen.
// Each on the CPU packets and on one ray per work-item (the two dvr marches that composite the
// layer; the surface pass itself is one kernel for both).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ball_scene.h"
#include "stability_helpers.h"
#include "surface_field.h"  // engine/src: the default sigma
#include "test_volumes.h"
#include "voxray/engine/camera.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/segmentation.h"

namespace voxray {

namespace {

constexpr double kSurfaceRadiusMm = 15.0;

// 48^3 voxels of 1 mm, all -1000 HU (the dvr table below leaves them transparent).
const Volume& emptyVolume() {
  static Volume v = test::ball({48, 48, 48}, 10.0, -1000.0, -1000.0, {1.0, 1.0, 1.0});
  return v;
}

// Voxels whose centres lie within R mm of C (mm from the volume's centre) get LABEL.
void addSphere(Segmentation& s, const Volume& v, glm::dvec3 c, double r, uint8_t label,
               glm::vec3 colour) {
  const glm::dvec3 mid = (glm::dvec3(v.dims) - 1.0) * 0.5;
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x)
        if (glm::length((glm::dvec3(x, y, z) - mid) * v.spacingMm - c) <= r)
          s.labels[s.grid.index(x, y, z)] = label;
  Segment seg;
  seg.label = label;
  seg.name = "Sphere " + std::to_string(label);
  seg.colour = colour;
  seg.display3d = Segment::Display3d::Surface;
  s.segments.push_back(seg);
}

// Orthographic dvr, a table transparent at every HU: only surfaces show, on black.
RenderParams surfaceView(int size) {
  RenderParams p;
  p.width = p.height = size;
  p.mode = Mode::Dvr;
  p.transferFunction = {{-2000.0, {1.0, 1.0, 1.0, 0.0}}, {3000.0, {1.0, 1.0, 1.0, 0.0}}};
  p.camera.projection = Projection::Orthographic;
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  p.stepMm = 0.5;
  return p;
}

Raycaster& raycaster(bool packets) {
  static Raycaster rc(test::pocl(), emptyVolume(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.packets = packets;
  rc.setOptions(o);
  return rc;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[size_t(std::lround(q * double(v.size() - 1)))];
}

struct NormalErrors {
  double median = 0.0, p95 = 0.0;
  size_t pixels = 0;
};

// The angle (degrees) between each hit's normal and the sphere's outward normal at the hit.
NormalErrors normalErrors(const std::vector<Raycaster::SurfaceHit>& hits) {
  std::vector<double> deg;
  for (const auto& h : hits) {
    if (h.label != 1) continue;
    const glm::dvec3 analytic = glm::normalize(glm::dvec3(h.pointMm));  // centre: the origin
    const double c =
        std::clamp(glm::dot(analytic, glm::normalize(glm::dvec3(h.normal))), -1.0, 1.0);
    deg.push_back(std::acos(c) * 180.0 / M_PI);
  }
  NormalErrors e;
  e.pixels = deg.size();
  if (deg.empty()) return e;
  e.median = percentile(deg, 0.5);
  e.p95 = percentile(deg, 0.95);
  return e;
}

bool dark(const Image& img, size_t i) {
  return img.rgba[4 * i] == 0 && img.rgba[4 * i + 1] == 0 && img.rgba[4 * i + 2] == 0;
}

}  // namespace

TEST(Surfaces, SphereSilhouetteAndNormalsAgreeWithTheAnalyticSphere) {
  const Volume& v = emptyVolume();
  Segmentation seg = emptySegmentation(v);
  addSphere(seg, v, glm::dvec3(0.0), kSurfaceRadiusMm, 1, {0.9f, 0.9f, 0.9f});
  const RenderParams p = surfaceView(160);
  // The pixel's size: neighbouring orthographic rays' origins.
  glm::dvec3 o0, o1, d;
  const ViewGeometry g = makeViewGeometry(v, p);
  g.ray(0, 0, p.width, p.height, o0, d);
  g.ray(1, 0, p.width, p.height, o1, d);
  const double pixelMm = glm::length(o1 - o0);
  const double analyticPx = kSurfaceRadiusMm / pixelMm;
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    Raycaster& rc = raycaster(packets);
    rc.setSurfaceSigma(kSurfaceSigmaVoxels);  // the workstation's
    rc.setSegmentation(seg);
    EXPECT_NE(rc.variantOptions(p).find("SURFACES=1"), std::string::npos);
    const Image img = rc.render(p);
    size_t covered = 0;
    for (size_t i = 0; i < size_t(p.width) * p.height; ++i) covered += !dark(img, i);
    const double measuredPx = std::sqrt(double(covered) / M_PI);
    std::printf("silhouette radius: %.3f px, analytic %.3f px (%.4f mm pixels)\n", measuredPx,
                analyticPx, pixelMm);
    // Half a pixel: the bound. The smoothing's own shrink (about sigma^2 / R = 0.07 mm,
    // 0.2 px here) and the voxelisation's stay inside it.
    EXPECT_NEAR(measuredPx, analyticPx, 0.5);

    const NormalErrors smooth = normalErrors(rc.surfaceHits(p));
    rc.setSurfaceSigma(0.0f);
    rc.setSegmentation(seg);
    const NormalErrors blocky = normalErrors(rc.surfaceHits(p));
    std::printf("normal error, smoothed field: median %.2f deg, 95th %.2f deg (%zu pixels)\n",
                smooth.median, smooth.p95, smooth.pixels);
    std::printf("normal error, blocky label surface: median %.2f deg, 95th %.2f deg\n",
                blocky.median, blocky.p95);
    // Every covered pixel has a hit with a normal.
    EXPECT_EQ(smooth.pixels, covered);
    // Seen here: smoothed 1.60 deg median, 4.59 deg 95th; blocky 9.06 and 24.92 deg. The
    // 1.25-voxel Gaussian leaves a ripple of the voxel stairs of a degree or two (sigma 1.5
    // gave 1.05 / 3.25, 2.0 0.59 / 1.98, at the cost of thin plates, surface_field.h); the
    // mask's trilinear gradient follows the stairs, tens of degrees off at their edges.
    // Bounds with room for rounding across devices, and the ratio the issue asks for.
    EXPECT_LT(smooth.median, 2.5);
    EXPECT_LT(smooth.p95, 6.0);
    EXPECT_GT(blocky.median, 4.0 * smooth.median);
    EXPECT_GT(blocky.p95, 4.0 * smooth.p95);
    rc.setSurfaceSigma(kSurfaceSigmaVoxels);
  }
}

TEST(Surfaces, TwoSegmentsShowTheirColoursAndAHiddenOneNothing) {
  const Volume& v = emptyVolume();
  Segmentation seg = emptySegmentation(v);
  addSphere(seg, v, {-10.0, 0.0, 0.0}, 8.0, 1, {1.0f, 0.0f, 0.0f});
  addSphere(seg, v, {10.0, 0.0, 0.0}, 8.0, 2, {0.0f, 1.0f, 0.0f});
  const RenderParams p = surfaceView(96);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    Raycaster& rc = raycaster(packets);
    rc.setSegmentation(seg);
    const Image img = rc.render(p);
    const std::vector<Raycaster::SurfaceHit> hits = rc.surfaceHits(p);
    int red = 0, green = 0;
    for (size_t i = 0; i < hits.size(); ++i) {
      const int r = img.rgba[4 * i], gr = img.rgba[4 * i + 1], b = img.rgba[4 * i + 2];
      if (hits[i].label == 0) {
        EXPECT_TRUE(dark(img, i)) << "pixel " << i;  // no surface: the black background
      } else if (hits[i].label == 1) {
        // Pure red shaded: the ambient 0.15 at least, the specular white alike in all three.
        EXPECT_GT(r, gr + 30) << "pixel " << i;
        EXPECT_EQ(gr, b) << "pixel " << i;
        ++red;
      } else {
        EXPECT_GT(gr, r + 30) << "pixel " << i;
        EXPECT_EQ(r, b) << "pixel " << i;
        ++green;
      }
    }
    // Each 8 mm sphere's disc: pi 8^2 mm^2 in pixels of (half extent ~ 41.6 mm / 48)^2 ...
    // both alike, each some hundreds of pixels.
    EXPECT_GT(red, 200);
    EXPECT_NEAR(double(green), double(red), 0.1 * red);

    // Hidden in 3D (and, alike, not visible): none of its pixels is drawn, the other stays.
    for (int how = 0; how < 2; ++how) {
      Segmentation h = seg;
      if (how == 0)
        h.segments[1].display3d = Segment::Display3d::Hidden;
      else
        h.segments[1].visible = false;
      rc.updateSegmentation(h, glm::ivec3(1), glm::ivec3(0));  // the list only
      const Image hidden = rc.render(p);
      const std::vector<Raycaster::SurfaceHit> after = rc.surfaceHits(p);
      for (size_t i = 0; i < hits.size(); ++i) {
        if (hits[i].label == 2) {
          EXPECT_TRUE(dark(hidden, i)) << "pixel " << i;
          EXPECT_EQ(after[i].label, 0);
        }
        if (hits[i].label == 1) {
          for (int c = 0; c < 3; ++c) EXPECT_EQ(hidden.rgba[4 * i + c], img.rgba[4 * i + c]);
        }
      }
    }
    // Neither a surface: the kernels compile without the pass (SURFACES=0), the pixels are the
    // plain volume's (black).
    Segmentation none = seg;
    for (Segment& s : none.segments) s.display3d = Segment::Display3d::Hidden;
    rc.updateSegmentation(none, glm::ivec3(1), glm::ivec3(0));
    EXPECT_NE(rc.variantOptions(p).find("SURFACES=0"), std::string::npos);
    const Image plain = rc.render(p);
    for (size_t i = 0; i < hits.size(); ++i) EXPECT_TRUE(dark(plain, i)) << "pixel " << i;
  }
}

TEST(Surfaces, FieldsAreBuiltForEditsOfTheLabelsOnly) {
  const Volume& v = emptyVolume();
  Segmentation seg = emptySegmentation(v);
  addSphere(seg, v, {-10.0, 0.0, 0.0}, 8.0, 1, {1.0f, 0.0f, 0.0f});
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  rc.setSegmentation(seg);
  EXPECT_EQ(rc.surfaceFieldBuilds(), 1);
  RenderParams p = surfaceView(32);
  rc.render(p);
  p.camera.azimuthDeg += 40.0;  // a camera move
  rc.render(p);
  seg.segments[0].colour = {0.0f, 0.0f, 1.0f};  // the list only
  rc.updateSegmentation(seg, glm::ivec3(1), glm::ivec3(0));
  rc.render(p);
  EXPECT_EQ(rc.surfaceFieldBuilds(), 1);
  // A voxel far from the sphere's padded box, of another label: not its field.
  seg.labels[seg.grid.index(46, 46, 46)] = 3;
  rc.updateSegmentation(seg, glm::ivec3(46), glm::ivec3(46));
  EXPECT_EQ(rc.surfaceFieldBuilds(), 1);
  // The sphere grows by a voxel there: built again.
  seg.labels[seg.grid.index(46, 46, 46)] = 1;
  rc.updateSegmentation(seg, glm::ivec3(46), glm::ivec3(46));
  EXPECT_EQ(rc.surfaceFieldBuilds(), 2);
}

TEST(Surfaces, ASurfaceInsideAnOpaqueDvrBallIsNotSeen) {
  // test_volumes.h's ball (radius 13 voxels, 1000 HU) opaque in the table; the surface sphere
  // of radius 6 mm inside it lies behind the ball's front: the dvr in front covers it.
  const Volume& v = test::anisotropicBall();
  Segmentation seg = emptySegmentation(v);
  addSphere(seg, v, glm::dvec3(0.0), 6.0, 1, {0.0f, 1.0f, 0.0f});
  RenderParams p = test::ballView(Mode::Dvr);
  p.transferFunction = {
      {-1000.0, {1.0, 1.0, 1.0, 0.0}}, {0.0, {1.0, 1.0, 1.0, 0.0}}, {500.0, {1.0, 0.2, 0.2, 1.0}}};
  // Packets, one ray per work-item, and the volume as an image (the GPUs' storage, one ray per
  // work-item) where the device has images.
  for (int path = 0; path < 3; ++path) {
    const bool packets = path == 0, image = path == 2;
    if (image && !test::pocl().device().imageSupport) continue;
    SCOPED_TRACE(packets ? "packets" : image ? "image3d" : "one ray per work-item");
    Raycaster rc(test::pocl(), v, image ? VolumeStorage::Image3d : VolumeStorage::Buffer);
    RaycasterOptions o;
    o.packets = packets;
    rc.setOptions(o);
    const Image plain = rc.render(p);
    rc.setSegmentation(seg);
    EXPECT_NE(rc.variantOptions(p).find("SURFACES=1"), std::string::npos);
    const Image with = rc.render(p);
    int hitPixels = 0;
    for (const auto& h : rc.surfaceHits(p)) hitPixels += h.label == 1;
    EXPECT_GT(hitPixels, 50);  // the surface is there, behind the ball's front
    // Early termination stops the rays at 0.99 opacity: what lies behind adds at most 1 % of
    // the surface's colour, 3 levels.
    for (size_t i = 0; i < plain.rgba.size(); ++i)
      EXPECT_NEAR(int(with.rgba[i]), int(plain.rgba[i]), 3) << "byte " << i;
    // Seen without the ball (the table transparent), the same surface is green.
    RenderParams clear = p;
    clear.transferFunction = {{-1000.0, {1.0, 1.0, 1.0, 0.0}}, {1000.0, {1.0, 1.0, 1.0, 0.0}}};
    const Image bare = rc.render(clear);
    int green = 0;
    // Pure green shaded: green at least the ambient 0.15 (38 levels) above red and blue, which
    // hold the white specular alone.
    for (size_t i = 0; i < bare.rgba.size() / 4; ++i)
      green +=
          bare.rgba[4 * i + 1] > bare.rgba[4 * i] + 30 && bare.rgba[4 * i] == bare.rgba[4 * i + 2];
    EXPECT_EQ(green, hitPixels);
  }
}

}  // namespace voxray
