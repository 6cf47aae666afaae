#pragma once
// The assertions every stability case makes: the frame renders on PoCL and through the
// reference renderer with no NaN/Inf, every pixel in [0, 1] (opaque alpha), the same
// image twice from each renderer, and agreement within a stated tolerance. Also the PoCL
// context and image difference other engine tests share.
#include <string>
#include <vector>

#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"
#include "voxray/io/volume.h"

namespace voxray::test {

// The modes every stability case renders.
inline constexpr Mode kAllModes[] = {Mode::Iso, Mode::Dvr, Mode::Mip};
// The lanes argument of the tests' render helpers that means one ray per work-item (no
// packets); 8 or 16 are a packet's rays, 0 the raycaster's choice.
inline constexpr int kPerRay = -1;

// The test device: PoCL ("cpu") unless VOXRAY_TEST_DEVICE names another (the GPU stability
// certificate, docs/stability/gpu-stability.sh, runs this suite on an NVIDIA GPU).
ClContext& pocl();
std::string testDeviceSelector();
// The volume storages expectStable renders with: VOXRAY_TEST_STORAGES ("buffer", "image" or
// both, comma-separated); buffer alone by default, which is what the CPU kernels use.
std::vector<VolumeStorage> testStorages();

// One frame of V on the test device, with or without packets.
Image renderKernel(const Volume& v, const RenderParams& p, bool packets);

// The largest difference between two images of the same size, in 8-bit levels.
int maxDiff(const Image& a, const Image& b);

// The kernel variant's name and whether it marched packets, for a failure's message.
std::string variantDescription(const RenderParams& p, bool packets);

// Tolerance between the PoCL image and the quantised reference, in 8-bit levels. The
// default is kernel_vs_reference_test.cpp's: float vs double can flip a first hit or a
// sample exactly on a threshold or a box face, so a few pixels may differ a lot.
struct Agreement {
  double meanAbs = 0.5;          // mean absolute difference per channel
  double fractionOver3 = 0.005;  // share of pixels more than 3 levels apart
};

void expectStable(const Volume& v, const RenderParams& p, const std::string& what,
                  Agreement tol = {});
// One storage's half of expectStable: two kernel frames against the quantised reference Q.
void expectAgrees(const Volume& v, const RenderParams& p, const Image& q, VolumeStorage storage,
                  Agreement tol);

// A small iso/dvr/mip parameter set that sees the whole volume.
RenderParams tinyParams(Mode mode, int width = 32, int height = 24);

}  // namespace voxray::test
