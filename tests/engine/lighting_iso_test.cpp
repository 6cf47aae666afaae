// iso frames with shadows on real CTs (issue 39, defect 6): iso's table gives every value
// the surface colour at opacity 1, air included, and the light grid (and the Monte Carlo
// reference) took the extinction from that table, so every shadow ray ran through "opaque
// air" and lit surfaces came out at the ambient term alone. The occluder of an iso frame is
// its iso range; the grid holds the fraction of each cell it fills.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "lighting_scenes.h"
#include "stability_helpers.h"
#include "voxray/engine/monte_carlo_reference.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/load.h"
#include "voxray/io/sample_volume.h"

namespace voxray {

namespace {

struct NamedCt {
  std::string name;
  Volume volume;
};

// The CTs the issue tried: the embedded sample (always there), and from the shared data
// when it is beside the checkout the tilted GE head and the Visible Human pelvis (512x512:
// a light grid cell of 4 voxels).
const std::vector<NamedCt>& realCts() {
  static const std::vector<NamedCt> cts = [] {
    std::vector<NamedCt> out;
    out.push_back({"sample CT", loadSampleCt()});
    const std::filesystem::path ge = std::filesystem::path(VOXRAY_SHARED_DATA) / "dicom/ct-ge-tilt";
    if (std::filesystem::is_directory(ge)) out.push_back({"GE tilt", loadVolume(ge.string())});
    const std::filesystem::path pelvis =
        std::filesystem::path(VOXRAY_SHARED_DATA) / "dicom/ct-visible-human-pelvis";
    if (std::filesystem::is_directory(pelvis))
      out.push_back({"pelvis", loadVolume(pelvis.string())});
    return out;
  }();
  return cts;
}

RenderParams isoFrame(Lighting l) {
  RenderParams p;  // iso from 400 HU (bone), the default camera
  p.width = 96;
  p.height = 72;
  p.lighting = l;
  p.camera.azimuthDeg = 30.0;
  return p;
}

// The mean grey (0..1) of an 8-bit RGBA image or a reference's RGB floats over
// the pixels where `surface` shows a surface (any channel off the background).
struct SurfaceMean {
  const Image& surface;
  glm::dvec3 background;
  bool hit(size_t i) const {
    for (int c = 0; c < 3; ++c)
      if (std::abs(surface.rgba[4 * i + size_t(c)] / 255.0 - background[c]) > 1.5 / 255.0)
        return true;
    return false;
  }
  template <class Channel>
  double of(Channel channel) const {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < surface.rgba.size() / 4; ++i)
      if (hit(i)) {
        sum += (channel(i, 0) + channel(i, 1) + channel(i, 2)) / 3.0;
        ++n;
      }
    // The pelvis's bone covers 3.8 % of the frame from this camera (260 pixels).
    EXPECT_GT(n, surface.rgba.size() / 4 / 40) << "the surface covers under 2.5 % of the image";
    return n ? sum / double(n) : 0.0;
  }
  double of(const Image& img) const {
    return of([&](size_t i, int c) { return img.rgba[4 * i + size_t(c)] / 255.0; });
  }
  double of(const std::vector<float>& rgb) const {
    return of([&](size_t i, int c) { return double(rgb[3 * i + size_t(c)]); });
  }
};

}  // namespace

// The light at the eye: every surface point the camera sees sees the light along the same
// ray, so nothing may shadow it and shadows should look like phong. Tolerance: the surface's
// mean grey at least 85 % of phong's (measured 92.3 % on the sample CT, 89.2 % on the GE
// head, 94.8 % on the pelvis: the light grid's cells of 2 and 4 voxels still reach the
// surface where the view grazes it and where the ray passes near other bone, more so on the
// GE head since its grid holds the whole tilted head, face and jaw included: 92.4 % when it
// held the table positions' range only); before the fix 20.8 and 21.1 % on the first two
// (little more than the ambient term).
TEST(LightingIso, ShadowsWithTheLightAtTheEyeLeaveEveryVisibleSurfaceLitOnRealCts) {
  for (const NamedCt& ct : realCts()) {
    RenderParams phong = isoFrame(Lighting::Phong), shadows = isoFrame(Lighting::Shadows);
    phong.light.position = shadows.light.position = glm::dvec3(0.0);  // at the eye
    for (bool packets : {true, false}) {
      SCOPED_TRACE(ct.name + (packets ? " packets" : " one ray"));
      const Image lit = test::renderKernel(ct.volume, phong, packets);
      const SurfaceMean mean{lit, phong.background};
      const double ratio = mean.of(test::renderKernel(ct.volume, shadows, packets)) / mean.of(lit);
      std::printf("%s %s: iso shadows / phong with the light at the eye %.3f\n", ct.name.c_str(),
                  packets ? "packets" : "one ray", ratio);
      EXPECT_GT(ratio, 0.85);
      EXPECT_LT(ratio, 1.0 + 1e-9);  // shadows only ever take light away
    }
  }
}

// The workstation's light (above right of the eye, following the camera) against the Monte
// Carlo reference, whose occluder in iso is the iso range too. The reference's lit surfaces
// keep most of phong's brightness (measured 0.925, 0.900 and 0.903 of it on the sample CT,
// the whole GE head and the pelvis: only folds and orbits darken; 0.21 and 0.20 on the first
// two before the fix, when the reference shared the defect and the kernel matched it at 60
// and 69 dB). The kernel's surface mean grey within 6 % of the reference's (measured 0.957,
// 0.961, 1.027) and above 28 dB (measured 29.9, 31.2 and 34.1 dB: below dvr's 35 dB goal, as
// opaque first-hit surfaces are the coarse grid's worst case).
TEST(LightingIso, ShadowsMatchTheMonteCarloReferenceOnRealCts) {
  for (const NamedCt& ct : realCts()) {
    SCOPED_TRACE(ct.name);
    RenderParams p = isoFrame(Lighting::Shadows), phong = isoFrame(Lighting::Phong);
    MonteCarloOptions o;
    o.samples = 4;
    const MonteCarloImage ref = renderMonteCarlo(ct.volume, p, o);
    const Image lit = test::renderKernel(ct.volume, phong, true),
                kernel = test::renderKernel(ct.volume, p, true);
    const SurfaceMean mean{lit, p.background};
    const double refRatio = mean.of(ref.mean.rgb) / mean.of(lit);
    const double kernelRatio = mean.of(kernel) / mean.of(ref.mean.rgb);
    const double db = test::psnr(kernel, ref.mean.rgb);
    std::printf("%s: reference / phong %.3f, kernel / reference %.3f, %.1f dB (se %.4f)\n",
                ct.name.c_str(), refRatio, kernelRatio, db, ref.meanStdError());
    EXPECT_GT(refRatio, 0.85);
    EXPECT_NEAR(kernelRatio, 1.0, 0.06);
    EXPECT_GT(db, 28.0);
  }
}

}  // namespace voxray
