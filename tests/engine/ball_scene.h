#pragma once
// The scene the kernel-vs-reference tests share (kernel_vs_reference, gradient_opacity,
// labels, overlay): the anisotropic ball, the camera that frames it in 64 x 48 pixels, labels
// and overlay's faint white table, and how near a float kernel's image must be to the double
// reference's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "test_volumes.h"
#include "voxray/engine/camera.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"
#include "voxray/io/segmentation.h"

namespace voxray::test {

// test_volumes.h's ball: 1000 HU inside -1000, radius 13 voxels, 40 x 36 x 24 voxels of
// 1 x 1.1 x 1.6 mm. Anisotropic on purpose: gradients and steps must be physical (per mm).
inline const Volume& anisotropicBall() {
  static Volume v = ball({40, 36, 24}, 13.0, 1000.0, -1000.0, {1.0, 1.1, 1.6});
  return v;
}

// A segment inside the ball: label 1 on the voxels within kSphereSegmentRadiusMm (mm) of the
// volume's centre, one segment "Sphere" of COLOUR (the labels and segment-table tests).
constexpr double kSphereSegmentRadiusMm = 6.0;
// Half the ball's voxel diagonal, 0.5 * |(1, 1.1, 1.6)| mm: how far a voxelised edge may lie.
constexpr double kBallHalfDiagonalMm = 1.09;
inline Segmentation sphereSegment(const Volume& v, glm::vec3 colour) {
  Segmentation s = emptySegmentation(v);
  const glm::dvec3 c = (glm::dvec3(v.dims) - 1.0) * 0.5;
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x)
        if (glm::length((glm::dvec3(x, y, z) - c) * v.spacingMm) <= kSphereSegmentRadiusMm)
          s.labels[s.grid.index(x, y, z)] = 1;
  Segment seg;
  seg.label = 1;
  seg.name = "Sphere";
  seg.colour = colour;
  s.segments.push_back(seg);
  return s;
}

// 64 x 48 pixels, azimuth 30, elevation 20, zoom 1.8 (the ball fills most of the frame).
inline RenderParams ballView(Mode mode) {
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.mode = mode;
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  p.camera.zoom = 1.8;
  return p;
}

// Dvr of the ball under a white, faint table, 0.5 mm steps: about half the light through the
// ball's middle, so the inside shows (labels_test, overlay_test).
inline RenderParams faintTableParams(bool shading = true) {
  RenderParams p = ballView(Mode::Dvr);
  p.shading = shading;
  p.transferFunction = {{-1000.0, {1.0, 1.0, 1.0, 0.0}},
                        {0.0, {1.0, 1.0, 1.0, 0.0}},
                        {1000.0, {1.0, 1.0, 1.0, 0.03}}};
  p.stepMm = 0.5;
  return p;
}

// Calls F(origin, direction) with each pixel's ray in G's frame (the direction a unit vector),
// row by row as the image's pixels lie.
template <class F>
void forEachPixelRay(const ViewGeometry& g, const RenderParams& p, F&& f) {
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      glm::dvec3 o, d;
      g.ray(x, y, p.width, p.height, o, d);
      f(o, d);
    }
}

// Each pixel's ray's distance from the volume's centre (row by row), and whether a ray at
// distance D surely crosses the sphere segment's voxels, or surely misses them (half a voxel
// diagonal of room each way, for the voxelised edge).
inline bool crossesSphereSegment(double d) {
  return d < kSphereSegmentRadiusMm - kBallHalfDiagonalMm;
}
inline bool missesSphereSegment(double d) {
  return d > kSphereSegmentRadiusMm + kBallHalfDiagonalMm + 0.05;
}
inline std::vector<double> sphereRayDistances(const Volume& v, const RenderParams& p) {
  std::vector<double> out;
  forEachPixelRay(makeViewGeometry(v, p), p, [&](const glm::dvec3& o, const glm::dvec3& d) {
    out.push_back(glm::length(glm::cross(-o, d)));  // d is a unit vector
  });
  return out;
}

struct ImageDiff {
  double meanAbs = 0.0;        // in 8-bit levels, over R, G and B of every pixel
  double fractionOver3 = 0.0;  // of pixels with a channel more than 3 levels apart
  int maxAbs = 0;
};

inline ImageDiff compareImages(const Image& a, const Image& b) {
  ImageDiff d;
  size_t n = size_t(a.width) * size_t(a.height), over = 0;
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      int e = std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c]));
      sum += e;
      worst = std::max(worst, e);
    }
    d.maxAbs = std::max(d.maxAbs, worst);
    if (worst > 3) ++over;
  }
  d.meanAbs = sum / double(n * 3);
  d.fractionOver3 = double(over) / double(n);
  return d;
}

// A float kernel against the double reference: the mean difference at most 0.5 levels, at
// most 0.5 % of pixels more than 3 levels apart (float rounding moves a sample across a
// voxel's or a table's edge now and then; a wrong formula moves many).
inline void expectCloseToReference(const Image& kernel, const Image& ref, const std::string& what) {
  ASSERT_EQ(kernel.width, ref.width) << what;
  ASSERT_EQ(kernel.rgba.size(), ref.rgba.size()) << what;
  const ImageDiff d = compareImages(kernel, ref);
  EXPECT_LE(d.meanAbs, 0.5) << what;
  EXPECT_LE(d.fractionOver3, 0.005) << what << " (max " << d.maxAbs << ")";
}

}  // namespace voxray::test
