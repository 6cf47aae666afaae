// The pinned upload path of the out-of-core renderer (OutOfCoreOptions::Upload::Pinned: host
// staging the runtime pins, copies on a transfer queue of their own, each part's kernel
// waiting for its copy), forced on PoCL, against the Direct path (the code before it, which
// a CPU device still takes): the same parts in the same order, the same evictions, the same
// bytes on the device, so the frames are equal bit for bit (a tolerance of 0: nothing in the
// pixels' arithmetic changed, only when and from where the slices were copied).
#include <gtest/gtest.h>

#include <cmath>

#include "stability_helpers.h"
#include "tall_volume.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/out_of_core.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

RenderParams view(Mode mode, double elevation, double azimuth = 35.0) {
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.mode = mode;
  p.shading = mode != Mode::Mip;
  if (mode == Mode::Iso) p.isoLo = 0.0;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  p.earlyTermination = 0.999;
  p.camera.azimuthDeg = azimuth;
  p.camera.elevationDeg = elevation;
  return p;
}

OutOfCoreOptions options(OutOfCoreOptions::Upload upload, bool ess = true,
                         VolumeStorage storage = VolumeStorage::Buffer) {
  OutOfCoreOptions o;
  o.budgetBytes = test::tallVolume().byteSize() / 2;
  o.partSlices = 4;  // 12-slice parts with their aprons: 8 parts, 3 held at once
  o.emptySpaceSkipping = ess;
  o.storage = storage;
  o.upload = upload;
  return o;
}

// Frames from elevation 90 down to -90 and back: the part order turns over, so the evictions
// differ from frame to frame. For each: the image, the uploads, the parts held.
void expectSameFrames(const OutOfCoreOptions& direct, const OutOfCoreOptions& pinned, Mode mode) {
  const Volume& v = test::tallVolume();
  auto srcA = volumeSlabSource(v), srcB = volumeSlabSource(v);
  OutOfCoreRenderer a(test::pocl(), *srcA, direct), b(test::pocl(), *srcB, pinned);
  ASSERT_EQ(a.partCount(), b.partCount());
  ASSERT_GT(a.partCount(), int(a.budgetBytes() / a.partBytesLargest()));  // out of core
  int uploads = 0;
  for (double elevation : {90.0, 25.0, 25.0, -90.0, -40.0, 90.0}) {
    const RenderParams p = view(mode, elevation);
    Image ia, ib;
    OutOfCoreStats sa, sb;
    a.render(p, ia, &sa);
    b.render(p, ib, &sb);
    const std::string at =
        toString(mode) + std::string(" at elevation ") + std::to_string(int(elevation));
    EXPECT_EQ(test::maxDiff(ia, ib), 0) << at;
    EXPECT_EQ(ia.rgba, ib.rgba) << at;
    EXPECT_EQ(sa.uploads, sb.uploads) << at;
    EXPECT_EQ(sa.bytesUploaded, sb.bytesUploaded) << at;
    EXPECT_EQ(sa.partsFull, sb.partsFull) << at;
    EXPECT_EQ(sa.partsResident, sb.partsResident) << at;
    EXPECT_EQ(a.residentParts(), b.residentParts()) << at;
    EXPECT_TRUE(sb.fullResolution) << at;
    EXPECT_EQ(sb.pinned, sb.uploads > 0) << at;
    EXPECT_FALSE(sa.pinned) << at;
    uploads += sb.uploads;
  }
  EXPECT_GT(uploads, a.partCount());  // parts went and came back
}

}  // namespace

TEST(OutOfCorePinned, EqualsDirectBitForBit) {
  using U = OutOfCoreOptions::Upload;
  for (Mode mode : {Mode::Dvr, Mode::Mip, Mode::Iso})
    expectSameFrames(options(U::Direct), options(U::Pinned), mode);
  expectSameFrames(options(U::Direct, false), options(U::Pinned, false), Mode::Dvr);
}

// Pinned uploads copy into an evicted part's device memory of the same size instead of
// releasing it and allocating anew (NVIDIA's runtime waited for a released buffer's launches):
// the frames stay those of Direct bit for bit with reuse on and off; with it on, only a part of
// another size (the two end parts: one apron, 8 slices against 12) allocates once the device is
// full, at most 2 a frame; off, every upload allocates, as Direct.
TEST(OutOfCorePinned, ReusesEvictedPartsMemory) {
  using U = OutOfCoreOptions::Upload;
  OutOfCoreOptions off = options(U::Pinned);
  off.reuseDeviceMemory = false;
  expectSameFrames(options(U::Direct), off, Mode::Dvr);
  for (VolumeStorage storage : {VolumeStorage::Buffer, VolumeStorage::Image3d}) {
    if (storage == VolumeStorage::Image3d && !test::pocl().device().imageSupport) continue;
    for (bool reuse : {true, false}) {
      OutOfCoreOptions o = options(U::Pinned, true, storage);
      o.reuseDeviceMemory = reuse;
      auto src = volumeSlabSource(test::tallVolume());
      OutOfCoreRenderer r(test::pocl(), *src, o);
      int uploads = 0, allocations = 0;
      int frameIndex = 0;
      for (double elevation : {90.0, -90.0, 90.0, -40.0}) {
        Image img;
        OutOfCoreStats s;
        r.render(view(Mode::Dvr, elevation), img, &s);
        const std::string at = std::string(reuse ? "reuse" : "no reuse") + " frame " +
                               std::to_string(frameIndex) +
                               (storage == VolumeStorage::Buffer ? " buffers" : " images");
        ASSERT_GT(s.uploads, 0) << at;
        if (!reuse) {
          EXPECT_EQ(s.allocations, s.uploads) << at;
        } else if (frameIndex > 0) {
          EXPECT_LE(s.allocations, 2) << at;
        }
        if (frameIndex > 0) uploads += s.uploads, allocations += s.allocations;
        ++frameIndex;
      }
      if (reuse) {
        EXPECT_LT(2 * allocations, uploads) << allocations << " allocations";
      }
      RecordProperty(std::string(reuse ? "reuse" : "no_reuse") + "_allocations_uploads",
                     std::to_string(allocations) + "/" + std::to_string(uploads));
    }
  }
}

// The storage GPUs take (image3d_t): the copies are image writes.
TEST(OutOfCorePinned, ImageStorageEqualsDirect) {
  if (!test::pocl().device().imageSupport) GTEST_SKIP() << "no image support";
  using U = OutOfCoreOptions::Upload;
  expectSameFrames(options(U::Direct, true, VolumeStorage::Image3d),
                   options(U::Pinned, true, VolumeStorage::Image3d), Mode::Dvr);
}

// Auto on a CPU device stays Direct (in-place slices, no copy): nothing pinned.
TEST(OutOfCorePinned, AutoOnCpuIsDirect) {
  auto src = volumeSlabSource(test::tallVolume());
  OutOfCoreRenderer r(test::pocl(), *src, options(OutOfCoreOptions::Upload::Auto));
  Image img;
  OutOfCoreStats s;
  r.render(view(Mode::Dvr, 25.0), img, &s);
  EXPECT_GT(s.uploads, 0);
  EXPECT_FALSE(s.pinned);
}

// The frame's times: read (host), copies and kernels (profiled), the stretch of the parts
// (host), and the overlap as their sum less that stretch. The kernels run one after another
// on one in-order queue inside the stretch; 1 ms of slack for the two clocks' rounding.
TEST(OutOfCorePinned, StatsSayReadUploadKernelAndOverlap) {
  auto src = volumeSlabSource(test::tallVolume());
  OutOfCoreRenderer r(test::pocl(), *src, options(OutOfCoreOptions::Upload::Pinned));
  Image img;
  OutOfCoreStats s;
  r.render(view(Mode::Dvr, 25.0), img, &s);  // the kernels built
  r.render(view(Mode::Dvr, -40.0), img, &s);
  ASSERT_TRUE(s.pinned);
  ASSERT_GT(s.uploads, 0);
  EXPECT_GT(s.readMs, 0.0);
  EXPECT_GT(s.uploadMs, 0.0);
  EXPECT_GT(s.kernelMs, 0.0);
  EXPECT_GT(s.partsMs, 0.0);
  EXPECT_LE(s.kernelMs, s.partsMs + 1.0);
  EXPECT_LE(s.partsMs, s.totalMs);
  EXPECT_NEAR(s.overlapMs, std::max(0.0, s.readMs + s.uploadMs + s.kernelMs - s.partsMs), 1e-9);
  EXPECT_LE(s.overlapMs, s.readMs + s.uploadMs + s.kernelMs);
}

// An allocation failure mid-frame (the fault hook: the device takes 2 parts where the budget
// says 3) on the pinned path: the same frame as the Direct path's, the parts it cannot take
// drawn coarse, flagged and explained; the next frame converges within what it held.
TEST(OutOfCorePinned, AllocationFailureAsDirect) {
  using U = OutOfCoreOptions::Upload;
  const Volume& v = test::tallVolume();
  auto srcA = volumeSlabSource(v), srcB = volumeSlabSource(v);
  OutOfCoreOptions od = options(U::Direct), op = options(U::Pinned);
  od.faultDeviceParts = op.faultDeviceParts = 2;
  OutOfCoreRenderer a(test::pocl(), *srcA, od), b(test::pocl(), *srcB, op);
  ASSERT_GE(b.budgetBytes() / b.partBytesLargest(), 3u);
  for (int frameIndex = 0; frameIndex < 2; ++frameIndex) {
    const RenderParams p = view(Mode::Dvr, 25.0);
    Image ia, ib;
    OutOfCoreStats sa, sb;
    ASSERT_NO_THROW(a.render(p, ia, &sa));
    ASSERT_NO_THROW(b.render(p, ib, &sb));
    EXPECT_EQ(sb.deviceOutOfMemory, frameIndex == 0);
    EXPECT_EQ(sb.fullResolution, frameIndex == 1);
    EXPECT_EQ(sa.deviceOutOfMemory, sb.deviceOutOfMemory);
    EXPECT_EQ(sa.partsCoarse, sb.partsCoarse);
    EXPECT_EQ(sa.partsFull, sb.partsFull);
    EXPECT_EQ(sa.partsResident, sb.partsResident);
    EXPECT_LE(sb.partsResident, 2);
    EXPECT_EQ(sa.message, sb.message);
    if (frameIndex == 0) {
      EXPECT_NE(sb.message.find("coarse level"), std::string::npos);
    }
    EXPECT_EQ(ia.rgba, ib.rgba) << "frame " << frameIndex;
  }
}

}  // namespace voxray
