// A volume larger than the device's largest allocation or 3D image must fail with a clear
// Error (Device), before anything is uploaded. Allocating gigabytes to provoke it is not
// cheap, so the test lowers the limits a fresh context reports (white box: the limits live
// in the context's DeviceInfo, read by Raycaster's upload).
#include <gtest/gtest.h>

#include "cl_context_impl.h"
#include "test_volumes.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray {

TEST(StabilityDeviceLimits, VolumeLargerThanTheLargestAllocationIsAClearDeviceError) {
  ClContext ctx("cpu");
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

TEST(StabilityDeviceLimits, VolumeLargerThanTheLargest3dImageIsAClearDeviceError) {
  ClContext ctx("cpu");
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
