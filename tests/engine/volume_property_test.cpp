// The transfer-function model users shape (issue 35): curves between points, the render table
// made from two independent lists, and opacity per unit distance.
#include <gtest/gtest.h>

#include <cmath>

#include "frame_setup.h"  // engine-internal
#include "test_volumes.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

VolumeProperty tent(TfCurve curve) {
  VolumeProperty vp;
  vp.curve = curve;
  vp.color = {{-1000.0, {0.0, 0.0, 0.0}}, {1000.0, {1.0, 1.0, 1.0}}};
  vp.opacity = {{-100.0, 0.0}, {100.0, 0.5}, {500.0, 0.2}, {900.0, 0.9}};
  return vp;
}

// The table's straight lines against the property's own curves at every HU of 1/8 HU.
double worstTableError(const VolumeProperty& vp, double lo, double hi) {
  TransferFunction table{renderTable(vp)};
  double worst = 0.0;
  for (double hu = lo; hu <= hi; hu += 0.125) {
    glm::dvec4 t = table.evaluate(hu);
    glm::dvec3 c = colorAt(vp, hu);
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(t[k] - c[k]));
    worst = std::max(worst, std::abs(t.a - opacityAt(vp, hu)));
  }
  return worst;
}

}  // namespace

TEST(VolumeProperty, LinearCurvesAreStraightBetweenPointsAndConstantBeyond) {
  const VolumeProperty vp = tent(TfCurve::Linear);
  EXPECT_DOUBLE_EQ(opacityAt(vp, -500.0), 0.0);
  EXPECT_DOUBLE_EQ(opacityAt(vp, 0.0), 0.25);
  EXPECT_DOUBLE_EQ(opacityAt(vp, 300.0), 0.35);
  EXPECT_DOUBLE_EQ(opacityAt(vp, 5000.0), 0.9);
  EXPECT_DOUBLE_EQ(colorAt(vp, 0.0).g, 0.5);
  EXPECT_DOUBLE_EQ(colorAt(vp, 500.0).r, 0.75);
  // The table holds both lists' points, so straight lines between them are the property.
  EXPECT_EQ(renderTable(vp).size(), 6u);
  EXPECT_LE(worstTableError(vp, -1200.0, 1200.0), 1e-15);  // rounding only
}

TEST(VolumeProperty, SmoothCurvesPassThroughThePointsAndNeverOvershoot) {
  const VolumeProperty vp = tent(TfCurve::Smooth);
  for (const OpacityNode& n : vp.opacity) EXPECT_DOUBLE_EQ(opacityAt(vp, n.x), n.opacity) << n.x;
  // Between two points the curve stays within their values: a peak at 100 HU stays 0.5,
  // the dip at 500 HU stays 0.2 (a cubic spline would dip below it towards 0).
  for (size_t i = 0; i + 1 < vp.opacity.size(); ++i) {
    const OpacityNode a = vp.opacity[i], b = vp.opacity[i + 1];
    for (double f = 0.0; f <= 1.0; f += 1.0 / 64) {
      double v = opacityAt(vp, a.x + f * (b.x - a.x));
      EXPECT_GE(v, std::min(a.opacity, b.opacity) - 1e-12) << a.x << " + " << f;
      EXPECT_LE(v, std::max(a.opacity, b.opacity) + 1e-12) << a.x << " + " << f;
    }
  }
  // Smooth: the slope is continuous at an inner point (differences 0.01 HU either side of
  // 700 HU, in a rising stretch, agree to 1e-4 per HU), where straight lines kink.
  auto slope = [&](const VolumeProperty& p, double x, double dx) {
    return (opacityAt(p, x + dx) - opacityAt(p, x)) / dx;
  };
  VolumeProperty rising = vp;
  rising.opacity = {{0.0, 0.0}, {300.0, 0.1}, {700.0, 0.5}, {900.0, 0.9}};
  EXPECT_NEAR(slope(rising, 300.0, 0.01), slope(rising, 300.0, -0.01), 1e-4);
  VolumeProperty straight = rising;
  straight.curve = TfCurve::Linear;
  EXPECT_GT(std::abs(slope(straight, 300.0, 0.01) - slope(straight, 300.0, -0.01)), 5e-4);
}

TEST(VolumeProperty, TheRenderTableFollowsASmoothCurveWithinOne1024th) {
  const VolumeProperty vp = tent(TfCurve::Smooth);
  const double worst = worstTableError(vp, -1200.0, 1200.0);
  EXPECT_LE(worst, 1.0 / 1024.0);
  // More points than the lists, and far fewer than one per HU.
  const size_t n = renderTable(vp).size();
  EXPECT_GT(n, 6u);
  EXPECT_LT(n, 400u) << "worst " << worst;
}

TEST(VolumeProperty, AStepInEitherListIsAStepInTheTable) {
  VolumeProperty vp;
  vp.color = {{0.0, {1.0, 0.0, 0.0}}, {200.0, {1.0, 0.0, 0.0}}, {200.0, {1.0, 1.0, 1.0}}};
  vp.opacity = {{-100.0, 0.0}, {300.0, 0.4}};
  for (TfCurve curve : {TfCurve::Linear, TfCurve::Smooth}) {
    vp.curve = curve;
    TransferFunction table{renderTable(vp)};
    EXPECT_DOUBLE_EQ(table.evaluate(199.999).g, 0.0);
    EXPECT_DOUBLE_EQ(table.evaluate(200.0).g, 1.0);
    // The opacity has no step at 200 HU: 0.3 there from both sides.
    EXPECT_NEAR(table.evaluate(199.999).a, 0.3, 1e-3);
    EXPECT_NEAR(table.evaluate(200.0).a, 0.3, 1e-3);
  }
}

TEST(VolumeProperty, OpacityPerUnitDistanceIsTheSameAbsorptionPerMillimetre) {
  // Voxels of 0.5 mm: the table is made per 0.5 mm. An opacity of 0.5 per 2 mm is
  // 1 - 0.5^(1/4) = 0.159104 per 0.5 mm, so four such steps absorb half.
  const Volume v = test::constant({8, 8, 8}, 100);
  Volume half = v;
  half.spacingMm = glm::dvec3(0.5);
  RenderParams p;
  p.mode = Mode::Dvr;
  p.transferFunction = {{-5000.0, {1.0, 1.0, 1.0, 0.5}}, {5000.0, {1.0, 1.0, 1.0, 0.5}}};
  p.opacityUnitMm = 2.0;
  const FrameSetup s = makeValueSetup(half, setupKeyOf(p));
  ASSERT_DOUBLE_EQ(s.referenceStepMm, 0.5);
  const double perStep = s.lut.lookup(100.0).a;
  EXPECT_NEAR(perStep, 0.159104, 1e-6);
  EXPECT_NEAR(1.0 - std::pow(1.0 - perStep, 4.0), 0.5, 1e-6);
  // Unit 0, or the reference step itself: the table's own opacities.
  for (double unit : {0.0, 0.5}) {
    p.opacityUnitMm = unit;
    EXPECT_FLOAT_EQ(float(makeValueSetup(half, setupKeyOf(p)).lut.lookup(100.0).a), 0.5f) << unit;
  }
}

TEST(VolumeProperty, APresetAsAPropertyMakesTheSameTable) {
  const Volume v = test::ball({16, 16, 16}, 5.0);
  for (const char* name : {"CT-Bone", "CT-Skin", "CT-Muscle", "MR-Default"}) {
    RenderParams preset;
    applyPreset(preset, findPreset(name));
    RenderParams custom;
    applyVolumeProperty(custom, volumePropertyOf(preset));
    EXPECT_EQ(frameTransferFunction(custom).points, frameTransferFunction(preset).points) << name;
    EXPECT_EQ(makeFrameSetup(v, custom).lut.rgba, makeFrameSetup(v, preset).lut.rgba) << name;
    EXPECT_EQ(custom.mode, Mode::Dvr);
    EXPECT_TRUE(custom.preset.empty());
  }
}

TEST(VolumeProperty, ApplyingTakesShadingSamplingAndTheUnit) {
  VolumeProperty vp = tent(TfCurve::Linear);
  vp.shade = false;
  vp.nearest = true;
  vp.ambient = 0.3;
  vp.diffuse = 0.6;
  vp.specular = 0.1;
  vp.specularPower = 12.0;
  vp.unitDistanceMm = 1.5;
  RenderParams p;
  p.preset = "CT-Bone";
  p.presetShiftHu = 40.0;
  applyVolumeProperty(p, vp);
  EXPECT_EQ(p.mode, Mode::Dvr);
  EXPECT_TRUE(p.preset.empty());
  EXPECT_EQ(p.presetShiftHu, 0.0);
  EXPECT_FALSE(p.shading);
  EXPECT_EQ(p.interp, Interp::Nearest);
  EXPECT_EQ(p.light.ambient, 0.3);
  EXPECT_EQ(p.light.diffuse, 0.6);
  EXPECT_EQ(p.light.specular, 0.1);
  EXPECT_EQ(p.light.shininess, 12.0);
  EXPECT_EQ(p.opacityUnitMm, 1.5);
  // Saved state keeps the unit: key=value text reads back to the same parameters.
  RenderParams back;
  fromText(back, toText(p));
  EXPECT_EQ(back.opacityUnitMm, 1.5);
  EXPECT_EQ(back.transferFunction, p.transferFunction);
}

// Issue 35: the gradient opacity reaches the render parameters (and saved state), linear
// points as they are, a smooth curve as straight pieces along it; all 1 changes nothing.
TEST(VolumeProperty, ApplyingTakesTheGradientOpacity) {
  VolumeProperty vp = tent(TfCurve::Linear);
  vp.gradientOpacity = {{0.0, 0.0}, {40.0, 0.5}, {100.0, 1.0}};
  RenderParams p;
  applyVolumeProperty(p, vp);
  ASSERT_EQ(p.gradientOpacity.size(), 3u);
  EXPECT_EQ(p.gradientOpacity[1], glm::dvec2(40.0, 0.5));
  RenderParams back;
  fromText(back, toText(p));
  EXPECT_EQ(back.gradientOpacity, p.gradientOpacity);
  EXPECT_EQ(findRenderParamSpec("gradient-opacity").format(p), "0:0,40:0.5,100:1");
  EXPECT_EQ(volumePropertyOf(p).gradientOpacity, vp.gradientOpacity);

  vp.curve = TfCurve::Smooth;
  applyVolumeProperty(p, vp);
  ASSERT_EQ(p.gradientOpacity.size(), 65u);
  EXPECT_EQ(p.gradientOpacity.front(), glm::dvec2(0.0, 0.0));
  EXPECT_EQ(p.gradientOpacity.back(), glm::dvec2(100.0, 1.0));
  for (const glm::dvec2& g : p.gradientOpacity)
    EXPECT_NEAR(g.y, gradientOpacityAt(vp, g.x), 1e-12) << g.x;

  vp.gradientOpacity = {{0.0, 1.0}, {50.0, 1.0}};  // factor 1 everywhere: off
  applyVolumeProperty(p, vp);
  EXPECT_TRUE(p.gradientOpacity.empty());
}

TEST(RenderParamsGradientOpacity, BadPointsAreRefusedWithTheRule) {
  RenderParams p;
  auto message = [&](const std::string& text) {
    try {
      findRenderParamSpec("gradient-opacity").parse(p, text);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message("10:0.5,0:0"), "");
  EXPECT_EQ(p.gradientOpacity, (std::vector<glm::dvec2>{{0.0, 0.0}, {10.0, 0.5}}));  // sorted
  EXPECT_NE(message("10:1.5").find("the factor A must lie in 0 ... 1, got '10:1.5'"),
            std::string::npos);
  EXPECT_NE(message("-1:0.5").find("0 or more), got '-1:0.5'"), std::string::npos);
  EXPECT_NE(message("10").find("each point is G:A"), std::string::npos);
  EXPECT_EQ(message(""), "");
  EXPECT_TRUE(p.gradientOpacity.empty());
}

TEST(VolumeProperty, ValidationNamesTheFieldThatIsWrong) {
  auto message = [](const VolumeProperty& vp) {
    try {
      validate(vp, "t.json");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  VolumeProperty ok = tent(TfCurve::Linear);
  EXPECT_EQ(message(ok), "accepted");
  VolumeProperty bad = ok;
  bad.opacity[2].opacity = 1.5;
  EXPECT_EQ(message(bad), "t.json: opacity point 3 has 1.5; it must lie in 0 ... 1");
  bad = ok;
  bad.opacity[2].x = 50.0;
  EXPECT_EQ(message(bad),
            "t.json: opacity point 3 (at 50) comes after one at 100; points must be sorted by "
            "position");
  bad = ok;
  bad.color[1].rgb.g = std::nan("");
  EXPECT_EQ(message(bad), "t.json: colour point 2 has nan; it must lie in 0 ... 1");
  bad = ok;
  bad.color[0].hu = INFINITY;
  EXPECT_EQ(message(bad), "t.json: colour point 1 is at a position that is not a finite number");
  bad = ok;
  bad.opacity.clear();
  EXPECT_EQ(message(bad), "t.json: opacity has no points; give at least one");
  bad = ok;
  bad.opacity.assign(kMaxTfPoints + 1, {0.0, 0.0});
  EXPECT_EQ(message(bad), "t.json: opacity has 4097 points; at most 4096 are read");
  bad = ok;
  bad.unitDistanceMm = -1.0;
  EXPECT_EQ(message(bad),
            "t.json: the unit distance must be 0 (one voxel) or a length in mm, got -1");
  bad = ok;
  bad.specular = 2.0;
  EXPECT_EQ(message(bad), "t.json: specular is 2; it must lie in 0 ... 1");
}

}  // namespace voxray
