// The kernels' sources as the device compiler gets them (kernelSource): files grouped in
// subfolders of kernels/ include one another by their path below it, from the embedded
// table and from VOXRAY_KERNEL_DIR alike.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "kernel_source.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// Sets VOXRAY_KERNEL_DIR for one scope (the rest of the suite reads the embedded table).
struct KernelDir {
  explicit KernelDir(const char* dir) { setenv("VOXRAY_KERNEL_DIR", dir, 1); }
  ~KernelDir() { unsetenv("VOXRAY_KERNEL_DIR"); }
};

}  // namespace

TEST(KernelSource, IncludesInSubfoldersAreResolved) {
  std::string raycast = kernelSource("raycast.cl");
  // One of each concern, reached through raycast.cl's includes.
  for (const char* what :
       {"inline void iso_packet(", "inline void dvr_packet(", "inline void mip_packet(",
        "inline uchar4 to_rgba8(", "inline float3 safe_normalize(", "inline int intersect_box(",
        "inline float sample_slab(", "} RaycastParams;"})
    EXPECT_NE(raycast.find(what), std::string::npos) << what;
  EXPECT_EQ(raycast.find("#include \""), std::string::npos);  // none left for the device
  EXPECT_NE(kernelSource("empty_space/classify.cl").find("__kernel void classify("),
            std::string::npos);
  EXPECT_NE(kernelSource("lighting/path_trace.cl").find("__kernel void path_trace("),
            std::string::npos);
}

TEST(KernelSource, AFolderGivesWhatIsEmbedded) {
  std::string embedded = kernelSource("raycast.cl");
  KernelDir dir(VOXRAY_KERNEL_SOURCE_DIR);
  EXPECT_EQ(kernelSource("raycast.cl"), embedded);
  EXPECT_EQ(kernelSource("lighting/light_volume.cl").empty(), false);
}

TEST(KernelSource, AMissingFileSaysWhichOne) {
  try {
    kernelSource("shading/no_such_kernel.cl");
    FAIL() << "a missing kernel was not refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Internal);
    EXPECT_NE(std::string(e.what()).find("shading/no_such_kernel.cl"), std::string::npos)
        << e.what();
  }
}

}  // namespace voxray
