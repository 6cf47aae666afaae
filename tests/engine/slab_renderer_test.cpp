// A part renderer that holds only its slab (MultiDeviceOptions::slab: an MPI rank's slices
// and apron, the whole volume's geometry without voxels) against the same range rendered from
// the whole volume's size with the slices outside the slab filled (what voxray-mpi held
// before): the same empty-space cells and the same part image, bit for bit (tolerance 0: the
// same stored slices reach the device and the same cells are classified).
#include <gtest/gtest.h>

#include <cmath>

#include "macro_cells.h"
#include "stability_helpers.h"
#include "streamed_cells.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/coarse_level.h"
#include "voxray/engine/multi_device.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// 37x29x61: sizes that are no multiple of the cell size, a ball crossing every slab.
const Volume& oddBall() {
  static Volume v = [] {
    Volume t;
    t.dims = {37, 29, 61};
    t.spacingMm = {1.0, 1.2, 0.8};
    t.originMm = {-10.0, 4.0, 30.0};
    t.voxels.resize(t.voxelCount());
    for (int z = 0; z < t.dims.z; ++z)
      for (int y = 0; y < t.dims.y; ++y)
        for (int x = 0; x < t.dims.x; ++x) {
          const double r =
              std::sqrt(std::pow((x - 18.0) / 14.0, 2) + std::pow((y - 14.0) / 11.0, 2) +
                        std::pow((z - 30.0) / 27.0, 2));
          const double hu =
              -1000.0 + 1900.0 / (1.0 + std::exp((r - 1.0) * 12.0)) + (x * 7 + z) % 13;
          t.voxels[t.index(x, y, z)] = int16_t(std::lround(hu));
        }
    return t;
  }();
  return v;
}

Volume slabOf(const Volume& v, int first, int end) {
  Volume s = withoutVoxels(v);
  s.dims.z = end - first;
  const size_t slice = size_t(v.dims.x) * size_t(v.dims.y);
  s.voxels.assign(v.voxels.begin() + std::ptrdiff_t(size_t(first) * slice),
                  v.voxels.begin() + std::ptrdiff_t(size_t(end) * slice));
  return s;
}

Volume filledOutside(const Volume& v, int first, int end, int16_t fill) {
  Volume f = v;
  const size_t slice = size_t(v.dims.x) * size_t(v.dims.y);
  for (size_t i = 0; i < f.voxels.size(); ++i) {
    const int z = int(i / slice);
    if (z < first || z >= end) f.voxels[i] = fill;
  }
  return f;
}

}  // namespace

// Slabs at the bottom, in the middle at offsets that are and are not multiples of the cell
// size, at the top, one slice thin, and the whole volume.
TEST(SlabCells, EqualTheFilledVolumesCells) {
  const Volume& v = oddBall();
  const int16_t fill = storedRange(v).min;
  for (auto [first, end] :
       {std::pair{0, 13}, std::pair{8, 24}, std::pair{9, 22}, std::pair{3, 7}, std::pair{30, 31},
        std::pair{45, 61}, std::pair{0, 61}, std::pair{52, 61}}) {
    const MacroCells want = computeMacroCells(filledOutside(v, first, end, fill));
    const MacroCells got = slabMacroCells(slabOf(v, first, end), first, v.dims.z, fill);
    EXPECT_EQ(got.dims, want.dims) << first << "-" << end;
    EXPECT_EQ(got.minMax, want.minMax) << "slab " << first << "-" << end;
  }
}

// Each range of 3 (planParts' split, apron 4), dvr, iso and mip, with and without empty-space
// skipping: the part image from the slab alone equals the one from the filled volume.
TEST(SlabRenderer, PartImageEqualsTheFilledVolumes) {
  const Volume& v = oddBall();
  const ValueRange range = storedRange(v);
  const Volume geometry = withoutVoxels(v);
  const std::vector<PartRange> ranges = planParts(v.dims.z, {1.0, 1.0, 1.0}, 4);
  ClContext& cl = test::pocl();
  for (const PartRange& r : ranges) {
    const Volume slab = slabOf(v, r.storedFirst, r.storedEnd);
    const Volume filled = filledOutside(v, r.storedFirst, r.storedEnd, range.min);
    for (bool ess : {true, false}) {
      MultiDeviceOptions o;
      o.ranges = {r};
      o.valueRange = range;
      o.emptySpaceSkipping = ess;
      o.storage = VolumeStorage::Buffer;
      MultiDeviceRenderer whole({&cl}, filled, o);
      o.slab = &slab;
      o.slabFirst = r.storedFirst;
      MultiDeviceRenderer alone({&cl}, geometry, o);
      for (Mode mode : {Mode::Dvr, Mode::Iso, Mode::Mip}) {
        RenderParams p;
        p.width = 48;
        p.height = 40;
        p.mode = mode;
        p.shading = mode != Mode::Mip;
        if (mode == Mode::Iso) p.isoLo = 0.0;
        if (mode == Mode::Dvr) p.preset = "CT-Bone";
        p.camera.azimuthDeg = 35.0;
        p.camera.elevationDeg = 25.0;
        EXPECT_EQ(whole.visibilityKeys(p), alone.visibilityKeys(p));
        const std::vector<PartImage> a = whole.renderParts(p);
        const std::vector<float> colour(a[0].colour, a[0].colour + 4 * 48 * 40),
            order(a[0].order, a[0].order + 48 * 40);
        const std::vector<PartImage> b = alone.renderParts(p);
        const std::string at = "slices " + std::to_string(r.first) + "-" + std::to_string(r.end) +
                               " " + toString(mode) + (ess ? " ess" : " no ess");
        EXPECT_EQ(colour, std::vector<float>(b[0].colour, b[0].colour + 4 * 48 * 40)) << at;
        EXPECT_EQ(order, std::vector<float>(b[0].order, b[0].order + 48 * 40)) << at;
        double lit = 0.0;
        for (size_t i = 3; i < colour.size(); i += 4) lit += colour[i];
        if (mode == Mode::Dvr) {
          EXPECT_GT(lit, 1.0) << at << ": the part draws something";
        }
      }
    }
  }
}

// A slab that does not hold its range's stored slices is refused, saying which.
TEST(SlabRenderer, SlabWithoutTheRangeIsRefused) {
  const Volume& v = oddBall();
  const PartRange r = planParts(v.dims.z, {1.0, 1.0}, 4)[1];
  const Volume slab = slabOf(v, r.storedFirst + 1, r.storedEnd);
  MultiDeviceOptions o;
  o.ranges = {r};
  o.valueRange = storedRange(v);
  o.slab = &slab;
  o.slabFirst = r.storedFirst + 1;
  const Volume geometry = withoutVoxels(v);
  try {
    MultiDeviceRenderer alone({&test::pocl()}, geometry, o);
    FAIL() << "a slab without its range's slices was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_NE(std::string(e.what()).find("not the stored slices"), std::string::npos) << e.what();
  }
}

}  // namespace voxray
