#include "stability_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"

namespace voxray::test {

int maxDiff(const Image& a, const Image& b) {
  int worst = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i)
    worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return worst;
}

Image renderKernel(const Volume& v, const RenderParams& p, bool packets) {
  Raycaster rc(pocl(), v);
  RaycasterOptions o = rc.options();
  o.packets = packets;
  rc.setOptions(o);
  return rc.render(p);
}

ClContext& pocl() {
  static ClContext ctx(testDeviceSelector());
  return ctx;
}

std::string testDeviceSelector() {
  const char* env = std::getenv("VOXRAY_TEST_DEVICE");
  return env && *env ? env : "cpu";
}

std::vector<VolumeStorage> testStorages() {
  const char* env = std::getenv("VOXRAY_TEST_STORAGES");
  std::string list = env && *env ? env : "buffer";
  std::vector<VolumeStorage> out;
  if (list.find("buffer") != std::string::npos) out.push_back(VolumeStorage::Buffer);
  if (list.find("image") != std::string::npos) out.push_back(VolumeStorage::Image3d);
  return out;
}

RenderParams tinyParams(Mode mode, int width, int height) {
  RenderParams p;
  p.width = width;
  p.height = height;
  p.mode = mode;
  p.isoLo = 0.0;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  return p;
}

void expectStable(const Volume& v, const RenderParams& p, const std::string& what, Agreement tol) {
  SCOPED_TRACE(what + " [" + toString(p.mode) + "]");
  FloatImage ref = renderReferenceFloat(v, p);
  size_t nonFinite = 0, outside = 0;
  for (float x : ref.rgb) {
    if (!std::isfinite(x))
      ++nonFinite;
    else if (x < 0.0f || x > 1.0f)
      ++outside;
  }
  EXPECT_EQ(nonFinite, 0u) << "reference pixels NaN/Inf";
  EXPECT_EQ(outside, 0u) << "reference pixels outside [0, 1]";
  FloatImage ref2 = renderReferenceFloat(v, p);
  EXPECT_TRUE(ref.rgb == ref2.rgb) << "reference not deterministic";

  Image q = quantise(ref);
  for (VolumeStorage storage : testStorages()) expectAgrees(v, p, q, storage, tol);
}

void expectAgrees(const Volume& v, const RenderParams& p, const Image& q, VolumeStorage storage,
                  Agreement tol) {
  SCOPED_TRACE(storage == VolumeStorage::Buffer ? "buffer" : "image3d");
  Raycaster rc(pocl(), v, storage);
  Image a = rc.render(p), b = rc.render(p);
  ASSERT_EQ(a.width, p.width);
  ASSERT_EQ(a.height, p.height);
  EXPECT_TRUE(a.rgba == b.rgba) << "kernel not deterministic: " << rc.variantOptions(p);
  size_t n = size_t(p.width) * size_t(p.height), over = 0, badAlpha = 0;
  double sum = 0.0;
  int worst = 0;
  for (size_t i = 0; i < n; ++i) {
    int px = 0;
    for (int c = 0; c < 3; ++c) {
      int e = std::abs(int(a.rgba[i * 4 + c]) - int(q.rgba[i * 4 + c]));
      sum += e;
      px = std::max(px, e);
    }
    worst = std::max(worst, px);
    over += px > 3;
    badAlpha += a.rgba[i * 4 + 3] != 255;
  }
  EXPECT_EQ(badAlpha, 0u) << "kernel left pixels unwritten";
  EXPECT_LE(sum / double(n * 3), tol.meanAbs) << rc.variantOptions(p);
  EXPECT_LE(double(over) / double(n), tol.fractionOver3)
      << rc.variantOptions(p) << " (max " << worst << " levels)";
}

std::string variantDescription(const RenderParams& p, bool packets) {
  return kernelVariantName(p) + (packets ? " packets" : " one ray per work-item");
}

}  // namespace voxray::test
