// Issue 38 part 2 in the workstation: the render worker draws a study larger than the device
// (or the GPU memory budget) out of core (out_of_core_view.h). The choice and the notes as
// values, then the real worker on PoCL: with a budget forcing 4 parts its still frame equals
// the in-core frame, a drag's frame is a flagged preview, and a device that runs out of memory
// gives coarse parts and the note, not an error.
//
// Tolerance: the converged frame is OutOfCoreRenderer's, which equals the one-device frame of
// a Raycaster marching one ray per work-item (packets off) within multi_device.h's bound: one
// 8-bit level per channel (float rounding of the composite across a rounding edge), plus
// 1 - earlyTermination for dvr, which these frames make 0.999 (0.26 of a level): so 1.
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>

#include "out_of_core_view.h"
#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "worker_frames.h"

namespace voxray {
namespace {

constexpr size_t kMiB = size_t(1) << 20;

ClContext& pocl() {
  static ClContext ctx("cpu");
  return ctx;
}

// The worker's frames (worker_frames.h), waiting up to 4 minutes for one: an out-of-core
// frame on PoCL marches one ray per work-item.
struct Frames : test::WorkerFrames {
  Frames() { wait = std::chrono::seconds(240); }
};

TEST(OutOfCoreChoice, UserBudgetDecidesElseTheDeviceLessItsHeadroom) {
  // A budget below the volume: out of core within it; at or above: in core.
  EXPECT_TRUE(chooseOutOfCore(100 * kMiB, 80000 * kMiB, 64 * kMiB).outOfCore);
  EXPECT_EQ(chooseOutOfCore(100 * kMiB, 80000 * kMiB, 64 * kMiB).budgetBytes, 64 * kMiB);
  EXPECT_FALSE(chooseOutOfCore(100 * kMiB, 80000 * kMiB, 100 * kMiB).outOfCore);
  // Automatic on 1 GiB: the headroom is 128 + 256 MiB, 640 MiB left for the volume.
  EXPECT_EQ(deviceHeadroomBytes(1024 * kMiB), 384 * kMiB);
  EXPECT_FALSE(chooseOutOfCore(640 * kMiB, 1024 * kMiB, 0).outOfCore);
  const OutOfCoreChoice big = chooseOutOfCore(641 * kMiB, 1024 * kMiB, 0);
  EXPECT_TRUE(big.outOfCore);
  EXPECT_EQ(big.budgetBytes, 640 * kMiB);
  // A device that says nothing of its memory: in core, as before.
  EXPECT_FALSE(chooseOutOfCore(641 * kMiB, 0, 0).outOfCore);
}

TEST(OutOfCoreChoice, WhatTheRendererDoesNotDrawIsTurnedOffAndSaid) {
  RenderParams p;
  p.mode = Mode::Dvr;
  p.lighting = Lighting::Shadows;
  p.preintegrate = true;
  p.stepMm = 5.0;
  p.adaptiveError = 0.02;
  const OutOfCoreParams o = outOfCoreParams(p, true, true, 2.0);
  EXPECT_EQ(o.params.lighting, Lighting::Phong);
  EXPECT_FALSE(o.params.preintegrate);
  EXPECT_DOUBLE_EQ(o.params.stepMm, 4.0);  // 2 slices of 2 mm
  EXPECT_DOUBLE_EQ(o.params.adaptiveError, 0.0);
  EXPECT_EQ(limitsNote(o.off),
            "Out of core, off: labels, fusion, shadows (lit by phong), pre-integration, steps "
            "over 2 slices");
  // The default look loses nothing: no note.
  RenderParams plain;
  plain.mode = Mode::Dvr;
  const OutOfCoreParams none = outOfCoreParams(plain, false, false, 1.0);
  EXPECT_TRUE(none.off.empty());
  EXPECT_EQ(limitsNote(none.off), "");
  EXPECT_EQ(toText(none.params), toText(plain));
}

TEST(OutOfCoreChoice, ResolutionNoteCountsTheFullParts) {
  OutOfCoreStats s;
  s.parts = 8;
  s.partsFull = 3;
  s.partsCoarse = 5;
  EXPECT_EQ(resolutionNote(s), "");  // fullResolution
  s.fullResolution = false;
  EXPECT_EQ(resolutionNote(s), "Not at full resolution (3 of 8 parts)");
  s.deviceOutOfMemory = true;
  EXPECT_EQ(resolutionNote(s), "Not at full resolution (3 of 8 parts); device out of memory");
  s.deviceOutOfMemory = false;
  s.shown = "preview";  // the source's quick level, before its coarse level is made
  EXPECT_EQ(resolutionNote(s),
            "Not at full resolution (3 of 8 parts); quick preview, the coarse level on its way");
}

// A CT-like ball, 96 x 96 x 64 (1.1 MiB): air, skin, a bone shell and brain in HU.
std::shared_ptr<Volume> ball() {
  auto v = std::make_shared<Volume>();
  v->dims = {96, 96, 64};
  v->spacingMm = {0.8, 0.8, 1.2};
  v->intercept = -1024.0;
  v->voxels.resize(v->voxelCount());
  const glm::ivec3 n = v->dims;
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) {
        const double dx = (x - n.x / 2.0) / (0.45 * n.x), dy = (y - n.y / 2.0) / (0.40 * n.y),
                     dz = (z - n.z / 2.0) / (0.47 * n.z);
        const double r = dx * dx + dy * dy + dz * dz;
        v->voxels[v->index(x, y, z)] = int16_t(r < 0.77   ? 1064
                                               : r < 0.86 ? 2024
                                               : r < 1.0  ? 1024
                                                          : 24);
      }
  return v;
}

RenderParams view(Mode mode) {
  RenderParams p;
  p.width = 96;
  p.height = 72;
  p.mode = mode;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  if (mode == Mode::Iso) p.isoLo = 400.0;
  p.earlyTermination = 0.999;
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  return p;
}

// Pixels brighter than 20 of 255 in red: the ball is there (the background is black).
int litPixels(const Image& a) {
  int lit = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) lit += a.rgba[i] > 20;
  return lit;
}

int maxDiff(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgba.size(), b.rgba.size());
  int worst = 0;
  for (size_t i = 0; i < std::min(a.rgba.size(), b.rgba.size()); ++i)
    worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return worst;
}

// 4 parts of 16 slices (24 stored with the aprons: 432 KiB each); a budget of 600 KiB holds
// one of them beside the coarse level and the cells, and is below the volume's 1.1 MiB.
OutOfCoreSettings fourParts() {
  OutOfCoreSettings o;
  o.budgetBytes = 600 * 1024;
  o.partSlices = 16;
  return o;
}

TEST(OutOfCoreWorker, ConvergedFrameEqualsInCoreAndADragFrameIsAFlaggedPreview) {
  const auto v = ball();
  ASSERT_GT(v->byteSize(), fourParts().budgetBytes);
  // Made before the worker's context: PoCL's device query is not safe from two threads.
  Raycaster inCore(pocl(), *v);  // the worker's storage (auto: a buffer on PoCL)
  Frames got;
  RenderWorker w("cpu", got.callbacks());
  w.setOutOfCore(fourParts());
  w.setVolume(v);
  RaycasterOptions ro;
  ro.packets = false;  // the parts march one ray per work-item
  inCore.setOptions(ro);
  for (Mode mode : {Mode::Dvr, Mode::Iso, Mode::Mip}) {
    const RenderParams p = view(mode);
    auto still = got.render(w, p, false);
    ASSERT_TRUE(still);
    EXPECT_TRUE(still->outOfCore);
    EXPECT_EQ(still->outOfCoreStats.parts, 4) << toString(mode);
    EXPECT_TRUE(still->outOfCoreStats.fullResolution);
    EXPECT_EQ(still->outOfCoreStats.partsFull, 4);
    EXPECT_EQ(still->resolutionNote, "");
    EXPECT_EQ(still->limitsNote, "");
    EXPECT_LE(still->outOfCoreStats.partsResident, 1);  // out of core indeed
    // Not an empty frame: the ball covers about an eighth of the view at the default distance.
    EXPECT_GT(litPixels(still->image), 96 * 72 / 10) << toString(mode);
    EXPECT_LE(maxDiff(still->image, inCore.render(p)), 1) << toString(mode);
    EXPECT_EQ(got.coarse, 1);  // the study's first image came from the coarse level, once

    // A drag from there: the part left on the device at full resolution, the others coarse.
    RenderParams drag = p;
    drag.camera.azimuthDeg += 10.0;
    auto preview = got.render(w, drag, true);
    ASSERT_TRUE(preview);
    EXPECT_TRUE(preview->interactive);
    EXPECT_FALSE(preview->outOfCoreStats.fullResolution);
    EXPECT_EQ(preview->outOfCoreStats.partsFull, 1);
    EXPECT_EQ(preview->outOfCoreStats.partsCoarse, 3);
    EXPECT_EQ(preview->outOfCoreStats.uploads, 0);  // a preview uploads nothing
    EXPECT_EQ(preview->resolutionNote, "Not at full resolution (1 of 4 parts)");
  }
}

// What the out-of-core renderer draws as the in-core one does, and so is not turned off: a 2D
// transfer function, gradient opacity, a clip box (the same bound as above).
TEST(OutOfCoreWorker, TwoDimensionalTableGradientOpacityAndClipMatchInCore) {
  const auto v = ball();
  Raycaster inCore(pocl(), *v);  // before the worker's context
  RaycasterOptions ro;
  ro.packets = false;
  inCore.setOptions(ro);
  Frames got;
  RenderWorker w("cpu", got.callbacks());
  w.setOutOfCore(fourParts());
  w.setVolume(v);
  RenderParams tf2d = view(Mode::Dvr);
  Tf2dPrimitive bone;
  bone.hu0 = 500.0;
  bone.hu1 = 1200.0;
  bone.g0 = 0.0;
  bone.g1 = 2000.0;
  bone.rgb = {0.9, 0.8, 0.6};
  bone.opacity = 0.6;
  bone.soft = 0.3;
  tf2d.tf2d.primitives = {bone};
  RenderParams gradient = view(Mode::Dvr);
  gradient.gradientOpacity = {{0.0, 0.2}, {200.0, 1.0}};
  RenderParams clip = view(Mode::Iso);
  clip.clip.hi.x = 0.6;  // the box's right face (0 ... 1 of the volume) moved in
  clip.clip.lo.z = 0.3;
  int index = 0;
  for (const RenderParams& p : {tf2d, gradient, clip}) {
    auto f = got.render(w, p, false);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->limitsNote, "") << index;
    EXPECT_GT(litPixels(f->image), 96 * 72 / 20) << index;
    EXPECT_LE(maxDiff(f->image, inCore.render(p)), 1) << index;
    ++index;
  }
}

// Shadows are the one-device Raycaster's: out of core the frame is lit by phong, and says so.
TEST(OutOfCoreWorker, LightingItCannotDrawIsOffWithANote) {
  const auto v = ball();
  Frames got;
  RenderWorker w("cpu", got.callbacks());
  w.setOutOfCore(fourParts());
  w.setVolume(v);
  const RenderParams phong = view(Mode::Dvr);
  auto plain = got.render(w, phong, false);
  ASSERT_TRUE(plain);
  RenderParams shadows = phong;
  shadows.lighting = Lighting::Shadows;
  auto f = got.render(w, shadows, false);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->limitsNote, "Out of core, off: shadows (lit by phong)");
  EXPECT_EQ(f->resolutionNote, "");
  EXPECT_EQ(maxDiff(f->image, plain->image), 0);  // the phong frame, not a silent other one
}

TEST(OutOfCoreWorker, AutomaticBudgetKeepsAFittingStudyInCoreByteForByte) {
  const auto v = ball();
  Raycaster inCore(pocl(), *v);  // before the worker's context, as above
  Frames got;
  RenderWorker w("cpu", got.callbacks());
  w.setVolume(v);
  const RenderParams p = view(Mode::Dvr);
  auto f = got.render(w, p, false);
  ASSERT_TRUE(f);
  EXPECT_FALSE(f->outOfCore);
  EXPECT_EQ(f->resolutionNote, "");
  EXPECT_EQ(maxDiff(f->image, inCore.render(p)), 0);
  // The budget set below the study: it opens again out of core; cleared: in core again, the
  // same bytes as before.
  w.setOutOfCore(fourParts());
  auto out = got.render(w, p, false);
  ASSERT_TRUE(out);
  EXPECT_TRUE(out->outOfCore);
  w.setOutOfCore({});
  auto back = got.render(w, p, false);
  ASSERT_TRUE(back);
  EXPECT_FALSE(back->outOfCore);
  EXPECT_EQ(maxDiff(back->image, f->image), 0);
}

TEST(OutOfCoreWorker, DeviceOutOfMemoryShowsCoarsePartsAndTheNote) {
  const auto v = ball();
  Frames got;
  RenderWorker w("cpu", got.callbacks());
  OutOfCoreSettings o = fourParts();
  o.budgetBytes = 1024 * 1024;  // 2 parts by the budget...
  o.faultDeviceParts = 1;       // ...but the device fails the second upload
  w.setOutOfCore(o);
  w.setVolume(v);
  auto f = got.render(w, view(Mode::Dvr), false);
  ASSERT_TRUE(f);
  EXPECT_EQ(got.error, "");
  EXPECT_TRUE(f->outOfCoreStats.deviceOutOfMemory);
  EXPECT_FALSE(f->outOfCoreStats.fullResolution);
  EXPECT_EQ(f->outOfCoreStats.partsFull + f->outOfCoreStats.partsCoarse, 4);
  EXPECT_GE(f->outOfCoreStats.partsCoarse, 1);
  EXPECT_EQ(f->resolutionNote.rfind("Not at full resolution (", 0), 0u) << f->resolutionNote;
  EXPECT_NE(f->resolutionNote.find("device out of memory"), std::string::npos);
  // The frames after it still come (within what the device held), never an error.
  auto next = got.render(w, view(Mode::Dvr), false);
  ASSERT_TRUE(next);
  EXPECT_EQ(got.error, "");
  EXPECT_FALSE(next->outOfCoreStats.fullResolution);
}

}  // namespace
}  // namespace voxray
