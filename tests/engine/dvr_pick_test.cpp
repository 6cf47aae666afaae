// The dvr pick (Raycaster::renderWithHits in dvr mode): each pixel's point where the
// accumulated opacity first reaches 0.5 (kernels/march/hit_output.cl), from the CPU packets
// (march_lanes.cl) and from one ray per work-item (the GPUs' kernel; on a buffer and on
// image3d_t), against the analytic answer: the same point on the same ray, found by
// integrating the transfer function of the analytic field (not of the voxels) in steps of
// 1e-3 voxel.
//
// The phantom is the synthetic sphere (48^3, 1 mm voxels, radius R = 16.45 voxels, value
// 100 HU per voxel of depth inside the surface), seen from the front left above in
// perspective at the default step (half a voxel) and shading.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "voxray/engine/camera.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/synthetic.h"

namespace voxray {
namespace {

constexpr double kThreshold = 0.5;  // DVR_HIT_ALPHA in kernels/march/hit_output.cl
const SyntheticSpec kSphere{SyntheticShape::Sphere, 48};
const double kRadius = 0.35 * (kSphere.size - 1);
const glm::dvec3 kCentre(0.5 * (kSphere.size - 1));

// White, with opacity (per voxel, the reference step) linear in HU between the points.
std::vector<ControlPoint> opacityRamp(std::vector<glm::dvec2> huOpacity) {
  std::vector<ControlPoint> tf;
  for (glm::dvec2 p : huOpacity) tf.push_back({p.x, glm::dvec4(1.0, 1.0, 1.0, p.y)});
  return tf;
}

RenderParams dvrParams(std::vector<ControlPoint> tf) {
  RenderParams p;
  p.width = 96;
  p.height = 72;
  p.mode = Mode::Dvr;
  p.transferFunction = std::move(tf);
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  return p;
}

struct PixelRay {
  glm::dvec3 o, d;  // voxel coordinates, d one voxel (1 mm) long
};

PixelRay pixelRay(const Volume& v, const RenderParams& p, int x, int y) {
  const ViewGeometry g = makeViewGeometry(v, p);
  glm::dvec3 o, d;
  g.ray(x, y, p.width, p.height, o, d);
  return {g.toVoxel(o), g.dirToVoxel(d)};
}

// The ray's closest approach to the sphere's centre, in voxels.
double missDistance(const PixelRay& r) {
  const glm::dvec3 c = kCentre - r.o;
  return glm::length(c - glm::dot(c, r.d) * r.d);
}

// Where the accumulated opacity 1 - exp(-integral of -ln(1 - a)) along the ray reaches
// the threshold, a the TF's opacity at the analytic field's value; none if it never does.
std::optional<glm::dvec3> analyticPick(const TransferFunction& tf, const PixelRay& r) {
  const AnalyticField field{kSphere};
  const glm::dvec3 c = kCentre - r.o;
  const double along = glm::dot(c, r.d), miss2 = glm::dot(c, c) - along * along;
  if (miss2 >= kRadius * kRadius) return std::nullopt;  // outside the sphere opacity is 0
  const double half = std::sqrt(kRadius * kRadius - miss2), h = 1e-3;
  const double target = -std::log(1.0 - kThreshold);
  double optical = 0.0;
  for (double s = along - half; s < along + half; s += h) {
    const double a = tf.evaluate(field.value(r.o + (s + 0.5 * h) * r.d)).a;
    if (a >= 1.0) return r.o + s * r.d;
    const double next = optical - std::log(1.0 - a) * h;
    if (next >= target) return r.o + (s + h * (target - optical) / (next - optical)) * r.d;
    optical = next;
  }
  return std::nullopt;
}

struct PickCheck {
  int expected = 0;    // pixels whose ray passes within 0.8 R of the centre
  int picked = 0;      // of those, with a hit
  int spurious = 0;    // hits where the analytic ray has none
  int nonFinite = 0;   // any component of any pixel not finite
  double worst = 0.0;  // voxels, over the expected pixels
};

// Compares every pixel's hit with the analytic pick; the error counts over rays that meet
// the surface at 37 degrees or less from its normal (miss distance <= 0.8 R): grazing rays
// cross the threshold over a long stretch, where half a step of sampling moves the point
// far along the ray. The error is the distance between the two points on the ray, which
// is more than their distance across the surface (by 1 / cos of the incidence).
PickCheck checkPicks(const Volume& v, const RenderParams& p, const std::vector<glm::vec4>& hits) {
  TransferFunction tf{p.transferFunction};
  PickCheck c;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const glm::vec4 h = hits[size_t(y) * size_t(p.width) + size_t(x)];
      if (!std::isfinite(h.x) || !std::isfinite(h.y) || !std::isfinite(h.z) || !std::isfinite(h.w))
        ++c.nonFinite;
      const PixelRay r = pixelRay(v, p, x, y);
      const std::optional<glm::dvec3> truth = analyticPick(tf, r);
      if (h.w >= 0.0F && !truth) ++c.spurious;
      if (!truth || missDistance(r) > 0.8 * kRadius) continue;
      ++c.expected;
      if (h.w < 0.0F) continue;
      ++c.picked;
      c.worst = std::max(c.worst, glm::distance(glm::dvec3(h), *truth));
    }
  return c;
}

// The kernels renderKernels runs, in its order.
const char* const kKernels[] = {"packets", "one ray per work-item", "one ray, image3d_t"};

// Renders with hits from the packets (the CPU default), from one ray per work-item on a
// buffer, and from one ray per work-item on image3d_t (the GPUs' kernel and storage, here on
// PoCL); checks that the hit output changes no pixel and that the variant is the one meant.
std::vector<std::vector<glm::vec4>> renderKernels(const Volume& v, const RenderParams& p) {
  ClContext ctx("cpu");
  std::vector<std::vector<glm::vec4>> out;
  for (VolumeStorage storage : {VolumeStorage::Buffer, VolumeStorage::Image3d}) {
    Raycaster rc(ctx, v, storage);
    for (bool packets : {true, false}) {
      if (packets && storage == VolumeStorage::Image3d) continue;  // packets read buffers
      RaycasterOptions o;
      o.packets = packets;
      rc.setOptions(o);
      std::vector<glm::vec4> hits;
      FrameStats stats;
      const Image img = rc.renderWithHits(p, hits, &stats);
      SCOPED_TRACE(stats.variant);
      EXPECT_NE(stats.variant.find("HIT_OUTPUT=1"), std::string::npos);
      EXPECT_EQ(stats.variant.find("PACKET=1") != std::string::npos, packets);
      EXPECT_EQ(stats.variant.find("STORAGE_IMAGE=1") != std::string::npos,
                storage == VolumeStorage::Image3d);
      EXPECT_EQ(rc.render(p).rgba, img.rgba);
      EXPECT_EQ(hits.size(), size_t(p.width) * size_t(p.height));
      out.push_back(std::move(hits));
    }
  }
  return out;
}

// Each kernel's picks of P's frame against the analytic ones (checkPicks: every ray that
// meets the surface within 37 degrees of its normal picks, within 0.05 voxel; no pick
// without an analytic one), and the centre pixel's ray, nearly along the normal, picks
// CENTREDEPTH voxels inside the surface.
void expectAnalyticPicks(const RenderParams& p, double centreDepth) {
  const Volume v = makeSyntheticVolume(kSphere);
  const auto kernels = renderKernels(v, p);
  for (size_t k = 0; k < kernels.size(); ++k) {
    SCOPED_TRACE(kKernels[k]);
    const PickCheck c = checkPicks(v, p, kernels[k]);
    EXPECT_GT(c.expected, 300);  // 348 of the 96 x 72 pixels
    EXPECT_EQ(c.picked, c.expected);
    EXPECT_EQ(c.spurious, 0);
    EXPECT_EQ(c.nonFinite, 0);
    EXPECT_LT(c.worst, 0.05);
    ::testing::Test::RecordProperty(std::string(kKernels[k]) + " worst voxels",
                                    std::to_string(c.worst));
    const glm::vec4 mid = kernels[k][size_t(p.height / 2) * size_t(p.width) + size_t(p.width / 2)];
    ASSERT_GE(mid.w, 0.0F);
    EXPECT_NEAR(glm::distance(glm::dvec3(mid), kCentre), kRadius - centreDepth, 0.05);
  }
}

// Opacity 0 at the surface (0 HU) rising to 1 one voxel inside (100 HU): the accumulated
// opacity reaches 0.5 where the integral of -ln(1 - x) over the depth x equals ln 2, at
// x = 0.910 voxel for a ray along the normal, so the picked points of central rays lie on
// the sphere of radius R - 0.910; obliquely the point lies on the ray at the same optical
// depth, shallower (analyticPick). Measured worst: 0.045 voxel, every kernel, at the most
// oblique rays counted, the picked point deeper than the truth (half-voxel steps sample the
// ramp's rising opacity at segment midpoints, so a little late).
TEST(DvrPick, OpaqueSphereWithinFiveHundredthsOfAVoxel) {
  expectAnalyticPicks(dvrParams(opacityRamp({{0.0, 0.0}, {100.0, 1.0}})), 0.910);
}

// A shell of opacity 0.1 per voxel (ramping from 0 over the outer voxel, 100 HU; the
// inside emptied below 1,200 HU deep, 12 voxels): along the normal the accumulated opacity
// reaches 0.5 at 7.09 voxels deep, after the ramp's optical depth 0.051 and 6.09 voxels of
// -ln 0.9 = 0.105 each. Measured worst: 0.039 voxel.
TEST(DvrPick, SemiTransparentShellAtTheAnalyticDepth) {
  expectAnalyticPicks(dvrParams(opacityRamp(
                          {{0.0, 0.0}, {100.0, 0.1}, {1200.0, 0.1}, {1200.0, 0.0}, {1700.0, 0.0}})),
                      7.09);
}

// The same shell at opacity 0.015: no ray through it gathers optical depth ln 2 (the
// longest chord, tangent to the empty inside, is 31 voxels: 0.47), so no pixel has a
// hit, though the shell shows.
TEST(DvrPick, RayBelowHalfOpacityHasNoHit) {
  const Volume v = makeSyntheticVolume(kSphere);
  const RenderParams p = dvrParams(
      opacityRamp({{0.0, 0.0}, {100.0, 0.015}, {1200.0, 0.015}, {1200.0, 0.0}, {1700.0, 0.0}}));
  const auto kernels = renderKernels(v, p);
  for (const auto& hits : kernels) {
    int none = 0;
    for (const glm::vec4& h : hits) none += h == glm::vec4(0.0F, 0.0F, 0.0F, -1.0F);
    EXPECT_EQ(none, p.width * p.height);
  }
  // The analytic rays agree: none through the centre or tangent to the empty inside.
  TransferFunction tf{p.transferFunction};
  EXPECT_FALSE(analyticPick(tf, {kCentre - glm::dvec3(0, 30, 0), glm::dvec3(0, 1, 0)}));
  EXPECT_FALSE(
      analyticPick(tf, {kCentre + glm::dvec3(kRadius - 12.0, -30, 0), glm::dvec3(0, 1, 0)}));
  // The shell is drawn: the centre pixel is not the (black) background.
  ClContext ctx("cpu");
  Raycaster rc(ctx, v, VolumeStorage::Buffer);
  const Image img = rc.render(p);
  const size_t mid = (size_t(p.height / 2) * size_t(p.width) + size_t(p.width / 2)) * 4;
  EXPECT_GT(int(img.rgba[mid]), 40);
}

// mip has no pick: every pixel says so, from every kernel.
TEST(DvrPick, MipFramesHaveNoHits) {
  const Volume v = makeSyntheticVolume(kSphere);
  RenderParams p = dvrParams({});
  p.mode = Mode::Mip;
  for (const auto& hits : renderKernels(v, p))
    for (const glm::vec4& h : hits) ASSERT_EQ(h, glm::vec4(0.0F, 0.0F, 0.0F, -1.0F));
}

}  // namespace
}  // namespace voxray
