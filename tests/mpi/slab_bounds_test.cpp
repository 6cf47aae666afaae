// Where a rank's slab can show (app/mpi/slab_bounds.h), checked against the rays themselves
// (ViewGeometry::ray and intersectBox, the renderers' own): no pixel outside the box has a ray
// that meets the slab, and the box is tight (a ray within two pixels inside each edge meets it).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "slab_bounds.h"
#include "voxray/engine/camera.h"
#include "voxray/io/volume.h"

namespace voxray::mpi {
namespace {

Volume anisotropicVolume() {
  Volume v;
  v.dims = {40, 44, 48};
  v.spacingMm = {1.0, 1.1, 1.3};
  v.voxels.resize(v.voxelCount());
  return v;
}

// Does the ray through the centre of pixel (PX, PY) meet the slab RANGE (the box
// slabBoundsNdc projects: its slices and one beyond either side, in the volume's box)?
bool rayMeetsSlab(const Volume& v, const RenderParams& p, const PartRange& range, int px, int py) {
  const ViewGeometry g = makeViewGeometry(v, p);
  glm::dvec3 o, d;
  g.ray(px, py, p.width, p.height, o, d);
  const glm::dvec3 lo(-0.5, -0.5, std::max(-0.5, range.first - 1.0));
  const glm::dvec3 hi(v.dims.x - 0.5, v.dims.y - 0.5, std::min(v.dims.z - 0.5, range.end + 1.0));
  double t0 = 0.0, t1 = 0.0;
  int axis = 0;
  return intersectBox(g.toVoxel(o), g.dirToVoxel(d), lo, hi, t0, t1, axis) && t1 > 0.0;
}

TEST(SlabBounds, NoRayOutsideTheBoxMeetsTheSlabAndTheBoxIsTight) {
  const Volume v = anisotropicVolume();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-180.0, 180.0), tilt(-80.0, 80.0);
  int checked = 0;
  for (int view = 0; view < 24; ++view) {
    RenderParams p;
    p.width = 96;
    p.height = 72;
    p.camera.azimuthDeg = angle(random);
    p.camera.elevationDeg = tilt(random);
    p.camera.zoom = view % 3 == 0 ? 2.5 : 1.0;
    p.camera.projection = view % 2 ? Projection::Orthographic : Projection::Perspective;
    const PartRange range{12 + view % 5, 30, 8, 34};
    const auto box = slabBoundsNdc(v, p, range);
    ASSERT_TRUE(box) << "view " << view << ": the eye is outside the volume";
    // Pixel centre (px + 0.5) / width * 2 - 1 in x, mirrored in y (rows top down).
    auto inside = [&](int px, int py) {
      const double x = 2.0 * (px + 0.5) / p.width - 1.0, y = 1.0 - 2.0 * (py + 0.5) / p.height;
      return x >= box->x0 && x <= box->x1 && y >= box->y0 && y <= box->y1;
    };
    int met = 0;
    for (int py = 0; py < p.height; ++py)
      for (int px = 0; px < p.width; ++px) {
        const bool meets = rayMeetsSlab(v, p, range, px, py);
        met += meets;
        if (!inside(px, py)) {
          EXPECT_FALSE(meets) << "view " << view << ": pixel " << px << "," << py
                              << " outside the box meets the slab";
          ++checked;
        }
      }
    ASSERT_GT(met, 0) << "view " << view;
    // Tight: the first and last columns and rows whose rays meet the slab lie within two
    // pixels of the box's edges (where they lie inside the image).
    int minX = p.width, maxX = -1, minY = p.height, maxY = -1;
    for (int py = 0; py < p.height; ++py)
      for (int px = 0; px < p.width; ++px)
        if (rayMeetsSlab(v, p, range, px, py)) {
          minX = std::min(minX, px);
          maxX = std::max(maxX, px);
          minY = std::min(minY, py);
          maxY = std::max(maxY, py);
        }
    const double pixelX = 2.0 / p.width, pixelY = 2.0 / p.height;
    auto ndcX = [&](int px) { return 2.0 * (px + 0.5) / p.width - 1.0; };
    auto ndcY = [&](int py) { return 1.0 - 2.0 * (py + 0.5) / p.height; };
    if (box->x0 > -1.0) {
      EXPECT_LE(ndcX(minX) - box->x0, 2.0 * pixelX) << "view " << view;
    }
    if (box->x1 < 1.0) {
      EXPECT_LE(box->x1 - ndcX(maxX), 2.0 * pixelX) << "view " << view;
    }
    if (box->y1 < 1.0) {
      EXPECT_LE(box->y1 - ndcY(minY), 2.0 * pixelY) << "view " << view;
    }
    if (box->y0 > -1.0) {
      EXPECT_LE(ndcY(maxY) - box->y0, 2.0 * pixelY) << "view " << view;
    }
  }
  EXPECT_GT(checked, 24 * 96 * 72 / 4);  // most views leave much of the image outside
}

TEST(SlabBounds, AnEyeInsideTheSlabHasNoBox) {
  const Volume v = anisotropicVolume();
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.camera.distanceMm = 1.0;  // 1 mm from the centre: inside every slab through the middle
  EXPECT_FALSE(slabBoundsNdc(v, p, PartRange{10, 38, 6, 42}));
}

}  // namespace
}  // namespace voxray::mpi
