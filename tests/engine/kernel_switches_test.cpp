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

TEST(KernelSwitches, EverySwitchIsPassedOnceAsALiteralOrItsSlot) {
  KernelSwitches s = kernelSwitches(frame(Mode::Dvr, Gradient::ZuckerHummel, Interp::Linear));
  s.PACKET = 1;
  s.LANES = 16;
  std::string special = switchOptions(s, false);
  EXPECT_EQ(count(special, "-D "), size_t(VOXRAY_SWITCH_COUNT) + 1);  // + VOXRAY_SWITCHES_SET
  EXPECT_EQ(count(special, " -D MODE=1"), 1u);
  EXPECT_EQ(count(special, " -D GRADIENT=2"), 1u);
  EXPECT_EQ(count(special, " -D LANES=16"), 1u);
  // RUNTIME: the bisection steps never make a program of their own.
  EXPECT_EQ(count(special, " -D REFINE_STEPS=P_SWITCH(VOXRAY_SLOT_REFINE_STEPS)"), 1u);

  std::string uber = switchOptions(s, true);
  EXPECT_EQ(count(uber, "-D "), size_t(VOXRAY_SWITCH_COUNT) + 1);
  EXPECT_EQ(count(uber, " -D MODE=P_SWITCH(VOXRAY_SLOT_MODE)"), 1u);
  EXPECT_EQ(count(uber, " -D ESS=P_SWITCH(VOXRAY_SLOT_ESS)"), 1u);
  EXPECT_EQ(count(uber, " -D LANES=16"), 1u);  // BUILD switches stay literals
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
  EXPECT_EQ(kernelVariantName(p), "iso_shaded_refine_steps4");
  p = frame(Mode::Mip, Gradient::Sobel, Interp::Linear);
  p.camera.projection = Projection::Orthographic;
  EXPECT_EQ(kernelVariantName(p), "mip_ortho");
}

}  // namespace voxray
