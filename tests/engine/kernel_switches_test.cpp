// The kernel switch list (kernels/switches.h) and what is generated from it: the rules that
// set the switches from a frame, the -D options, the slots of the frame parameters and the
// variant names. (That the uber kernel, reading every FRAME switch at run time, draws what the
// specialised ones draw: empty_space_test.cpp.)
#include <gtest/gtest.h>

#include <string>

#include "kernel_params.h"
#include "kernel_switches.h"
#include "stability_helpers.h"
#include "voxray/engine/kernel_variant.h"

namespace voxray {

namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

RenderParams frame(Mode mode, Gradient gradient, Interp interp) {
  RenderParams p = test::tinyParams(mode);
  p.gradient = gradient;
  p.interp = interp;
  return p;
}

// The tuning entries of switches.h (VOXRAY_TUNING), counted.
int tuningCount() {
  int n = 0;
#define VOXRAY_SWITCH(NAME, DEFAULT, KIND, LABELS)
#define VOXRAY_TUNING(NAME, AT_8_LANES, AT_16_LANES) ++n;
#include "switches.h"
#undef VOXRAY_TUNING
#undef VOXRAY_SWITCH
  return n;
}

}  // namespace

TEST(KernelSwitches, SwitchesThatCannotMatterKeepTheirDefaults) {
  KernelSwitches mip = kernelSwitches(frame(Mode::Mip, Gradient::ZuckerHummel, Interp::Linear));
  EXPECT_EQ(mip.MODE, 2);
  EXPECT_EQ(mip.SHADING, 0);  // mip is never shaded
  EXPECT_EQ(mip.GRADIENT, 0);
  EXPECT_EQ(mip.REFINE_STEPS, 0);
  EXPECT_EQ(mip.OPACITY_CORRECTION, 0);

  RenderParams iso = frame(Mode::Iso, Gradient::Sobel, Interp::Nearest);
  iso.refine = 7;
  KernelSwitches s = kernelSwitches(iso);
  EXPECT_EQ(s.SHADING, 1);
  EXPECT_EQ(s.GRADIENT, 1);
  EXPECT_EQ(s.INTERP, 0);
  EXPECT_EQ(s.REFINE_STEPS, 7);
  EXPECT_EQ(s.OPACITY_CORRECTION, 0);  // dvr only
  iso.shading = false;
  EXPECT_EQ(kernelSwitches(iso).GRADIENT, 0);  // no gradient is taken

  RenderParams dvr = frame(Mode::Dvr, Gradient::Central, Interp::Linear);
  EXPECT_EQ(kernelSwitches(dvr).OPACITY_CORRECTION, 1);
  EXPECT_EQ(kernelSwitches(dvr).REFINE_STEPS, 0);  // iso only
  dvr.camera.projection = Projection::Orthographic;
  dvr.jitter = true;
  EXPECT_EQ(kernelSwitches(dvr).ORTHO, 1);
  EXPECT_EQ(kernelSwitches(dvr).JITTER, 1);
}

// Issue 35: the gradient opacity is dvr's, off without points, takes the gradient operator
// even unshaded, and turns adaptive steps off (their levels read the colour table alone).
TEST(KernelSwitches, GradientOpacityIsDvrsAndTurnsAdaptiveStepsOff) {
  RenderParams dvr = frame(Mode::Dvr, Gradient::Sobel, Interp::Linear);
  dvr.adaptiveError = 0.01;
  dvr.shading = false;
  EXPECT_EQ(kernelSwitches(dvr).GRADIENT_OPACITY, 0);
  EXPECT_EQ(kernelSwitches(dvr).GRADIENT, 0);
  EXPECT_EQ(kernelSwitches(dvr).ADAPTIVE, 1);
  dvr.gradientOpacity = {{0.0, 0.0}, {100.0, 1.0}};
  KernelSwitches s = kernelSwitches(dvr);
  EXPECT_EQ(s.GRADIENT_OPACITY, 1);
  EXPECT_EQ(s.GRADIENT, 1);
  EXPECT_EQ(s.ADAPTIVE, 0);
  EXPECT_EQ(variantName(s), "dvr_sobel_oc_gopacity");
  for (Mode m : {Mode::Iso, Mode::Mip}) {
    RenderParams other = dvr;
    other.mode = m;
    EXPECT_EQ(kernelSwitches(other).GRADIENT_OPACITY, 0) << toString(m);
  }
}

TEST(KernelSwitches, EverySwitchIsPassedOnceAsALiteralOrItsSlot) {
  KernelSwitches s = kernelSwitches(frame(Mode::Dvr, Gradient::ZuckerHummel, Interp::Linear));
  s.PACKET = 1;
  s.LANES = 16;
  std::string special = switchOptions(s, false);
  // + VOXRAY_SWITCHES_SET, + the packets' tuning
  EXPECT_EQ(count(special, "-D "), size_t(VOXRAY_SWITCH_COUNT) + 1 + size_t(tuningCount()));
  EXPECT_EQ(count(special, " -D MODE=1"), 1u);
  EXPECT_EQ(count(special, " -D GRADIENT=2"), 1u);
  EXPECT_EQ(count(special, " -D LANES=16"), 1u);
  // RUNTIME: the bisection steps never make a program of their own.
  EXPECT_EQ(count(special, " -D REFINE_STEPS=P_SWITCH(VOXRAY_SLOT_REFINE_STEPS)"), 1u);

  std::string uber = switchOptions(s, true);
  EXPECT_EQ(count(uber, "-D "), size_t(VOXRAY_SWITCH_COUNT) + 1 + size_t(tuningCount()));
  EXPECT_EQ(count(uber, " -D MODE=P_SWITCH(VOXRAY_SLOT_MODE)"), 1u);
  EXPECT_EQ(count(uber, " -D ESS=P_SWITCH(VOXRAY_SLOT_ESS)"), 1u);
  EXPECT_EQ(count(uber, " -D LANES=16"), 1u);  // BUILD switches stay literals
}

TEST(KernelSwitches, TheRaycastersFactsSetStorageOutputAndPackets) {
  RenderParams mip = frame(Mode::Mip, Gradient::Central, Interp::Linear);
  KernelFacts f;
  f.storageImage = true;
  f.slabs = 3;
  f.countSamples = true;
  f.hitOutput = true;
  KernelSwitches s = kernelSwitches(mip, f);
  EXPECT_EQ(s.STORAGE_IMAGE, 1);
  EXPECT_EQ(s.SLABS, 3);
  EXPECT_EQ(s.COUNT_SAMPLES, 1);
  EXPECT_EQ(s.HIT_OUTPUT, 1);
  EXPECT_EQ(s.ESS, 0);
  EXPECT_EQ(s.PACKET, 0);  // one ray per work-item
  EXPECT_EQ(s.MIP_HALVES, 1);

  f = KernelFacts{};
  f.packetLanes = 8;
  s = kernelSwitches(mip, f);
  EXPECT_EQ(s.PACKET, 1);
  EXPECT_EQ(s.LANES, 8);
  EXPECT_EQ(s.MIP_HALVES, 2);  // two 4 x 2 packets a work-item
  f.packetLanes = 16;
  EXPECT_EQ(kernelSwitches(mip, f).MIP_HALVES, 1);

  // iso passes empty voxel blocks in 8-lane packets with ESS only (their bits ride with it).
  RenderParams iso = frame(Mode::Iso, Gradient::Central, Interp::Linear);
  f.packetLanes = 8;
  EXPECT_EQ(kernelSwitches(iso, f).ISO_BLOCK_TRIES, 0);
  f.emptySpaceSkipping = true;
  EXPECT_EQ(kernelSwitches(iso, f).ESS, 1);
  EXPECT_EQ(kernelSwitches(iso, f).ISO_BLOCK_TRIES, 4);
  f.packetLanes = 16;
  EXPECT_EQ(kernelSwitches(iso, f).ISO_BLOCK_TRIES, 0);

  // Adaptive steps read their levels from the macro cells: ESS or not at all.
  RenderParams dvr = frame(Mode::Dvr, Gradient::Central, Interp::Linear);
  dvr.adaptiveError = 0.01;
  ASSERT_EQ(kernelSwitches(dvr).ADAPTIVE, 1);
  EXPECT_EQ(kernelSwitches(dvr, f).ADAPTIVE, 1);
  f.emptySpaceSkipping = false;
  EXPECT_EQ(kernelSwitches(dvr, f).ADAPTIVE, 0);
}

TEST(KernelSwitches, PacketsGetTheTuningOfTheirLanes) {
  KernelSwitches s = kernelSwitches(frame(Mode::Iso, Gradient::Central, Interp::Linear));
  EXPECT_EQ(count(switchOptions(s, false), "ISO_BATCH"), 0u);  // one ray per work-item
  s.PACKET = 1;
  s.LANES = 8;
  std::string at8 = switchOptions(s, false);
  EXPECT_EQ(count(at8, " -D ISO_BATCH=4"), 1u);
  EXPECT_EQ(count(at8, " -D MIP_REFILL=4"), 1u);
  EXPECT_EQ(count(at8, " -D DVR_BATCH=2"), 1u);
  EXPECT_EQ(count(at8, " -D MIP_BATCH=4"), 1u);
  EXPECT_EQ(count(at8, " -D MIP_PREFETCH=1"), 1u);
  EXPECT_EQ(count(at8, " -D MIP_PREFETCH_FROM=1 -D MIP_PREFETCH_TO=1"), 1u);
  s.LANES = 16;
  std::string at16 = switchOptions(s, false);
  EXPECT_EQ(count(at16, " -D ISO_BATCH=2"), 1u);
  EXPECT_EQ(count(at16, " -D MIP_REFILL=2"), 1u);
  EXPECT_EQ(count(at16, " -D MIP_BATCH=4"), 1u);
}

TEST(KernelSwitches, EachSwitchSitsInItsSlot) {
  KernelSwitches s;
  s.MODE = 2;
  s.REFINE_STEPS = 9;
  s.LANES = 16;
  RaycastParams k{};
  packSwitches(s, k);
  auto slot = [&](int i) { return k.switches[i / 4].s[i % 4]; };
  EXPECT_EQ(slot(VOXRAY_SLOT_MODE), 2);
  EXPECT_EQ(slot(VOXRAY_SLOT_REFINE_STEPS), 9);
  EXPECT_EQ(slot(VOXRAY_SLOT_LANES), 16);
  EXPECT_EQ(slot(VOXRAY_SLOT_INTERP), 1);  // its default
  EXPECT_EQ(slot(VOXRAY_SLOT_SLABS), 1);
}

TEST(KernelSwitches, VariantNamesComeFromTheLabels) {
  RenderParams p = frame(Mode::Dvr, Gradient::ZuckerHummel, Interp::Nearest);
  EXPECT_EQ(kernelVariantName(p), "dvr_shaded_zh_nearest_oc");
  p = frame(Mode::Iso, Gradient::Central, Interp::Linear);
  p.refine = 4;
  EXPECT_EQ(kernelVariantName(p), "iso_shaded_central_refine_steps4");  // the default named too
  p.shading = false;
  EXPECT_EQ(kernelVariantName(p), "iso_refine_steps4");  // no gradient taken, none named
  p = frame(Mode::Mip, Gradient::Sobel, Interp::Linear);
  p.camera.projection = Projection::Orthographic;
  EXPECT_EQ(kernelVariantName(p), "mip_ortho");
}

}  // namespace voxray
