// A volume larger than the device's largest allocation or 3D image is split into z slabs;
// one that cannot be split within the limits must fail with a clear Error (Device), before
// anything is uploaded. Allocating gigabytes to provoke it is not cheap, so the tests lower
// the limits a fresh context reports (white box: the limits live in the context's
// DeviceInfo, read by Raycaster's upload).
#include <gtest/gtest.h>

#include "cl_context_impl.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray {

TEST(StabilityDeviceLimits, VolumeLargerThanTheLargestAllocationIsAClearDeviceError) {
  ClContext ctx(test::testDeviceSelector());
  ctx.impl().info.maxAllocBytes = 1000;  // the 16^3 volume needs 8192 bytes
  Volume v = test::constant({16, 16, 16}, 0);
  try {
    Raycaster rc(ctx, v, VolumeStorage::Buffer);
    FAIL() << "no error for a volume over the allocation limit";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Device);
    std::string m = e.what();
    EXPECT_NE(m.find("16x16x16"), std::string::npos) << m;
    EXPECT_NE(m.find("largest allocation"), std::string::npos) << m;
  }
}

TEST(StabilityDeviceLimits, VolumeLargerThanTheLargestAllocationIsSplitIntoSlabs) {
  ClContext ctx(test::testDeviceSelector());
  ctx.impl().info.maxAllocBytes = 8 * 16 * 16 * 2;  // 8 of the 16 slices
  Volume v = test::constant({16, 16, 16}, 0);
  Raycaster rc(ctx, v, VolumeStorage::Buffer);
  EXPECT_EQ(rc.slabCount(), 4);  // 4 slices each, 2 of apron each side
}

TEST(StabilityDeviceLimits, VolumeDeeperThanTheLargest3dImageIsSplitIntoSlabs) {
  ClContext ctx(test::testDeviceSelector());
  if (!ctx.device().imageSupport) GTEST_SKIP() << "no image support";
  ctx.impl().info.maxImage3d[2] = 10;
  Volume v = test::constant({4, 4, 16}, 0);
  Raycaster rc(ctx, v, VolumeStorage::Image3d);
  EXPECT_EQ(rc.slabCount(), 2);  // 8 slices each, 2 of apron on the inner side
}

TEST(StabilityDeviceLimits, VolumeLargerThanTheLargest3dImageIsAClearDeviceError) {
  ClContext ctx(test::testDeviceSelector());
  ctx.impl().info.imageSupport = true;
  ctx.impl().info.maxImage3d[0] = 8;
  Volume v = test::constant({16, 4, 4}, 0);
  try {
    Raycaster rc(ctx, v, VolumeStorage::Image3d);
    FAIL() << "no error for a volume over the 3D image limit";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Device);
    EXPECT_NE(std::string(e.what()).find("largest 3D image"), std::string::npos) << e.what();
  }
}

}  // namespace voxray
