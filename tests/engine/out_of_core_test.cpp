// A volume larger than a device budget on one device (voxray/engine/out_of_core.h, issue 38
// part 2), against the in-core one-device frame.
//
// Tolerance: the converged frame is multi_device.h's sort-last frame (its parts, the same
// kernel, the same "over"/max/nearest hit), so its bound holds: one 8-bit level per channel
// (float rounding of the composite across a rounding edge), and dvr's early termination adds
// at most 1 - earlyTermination, which the frames here make 0.999 (0.26 of a level).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "stability_helpers.h"
#include "streamed_cells.h"
#include "tall_volume.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/out_of_core.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"
#include "voxray/io/raw_import.h"
#ifdef VOXRAY_HAS_ZARR
#include "voxray/io/ome_zarr.h"
#endif

namespace voxray {

namespace {

using test::tallVolume;

enum class View { AlongPlusZ, AlongMinusZ, Oblique, Inside };
const char* name(View v) {
  return v == View::AlongPlusZ    ? "along+z"
         : v == View::AlongMinusZ ? "along-z"
         : v == View::Oblique     ? "oblique"
                                  : "eye-inside";
}

RenderParams frame(Mode mode, View v, int w = 64, int h = 48) {
  RenderParams p;
  p.width = w;
  p.height = h;
  p.mode = mode;
  p.shading = mode != Mode::Mip;
  if (mode == Mode::Iso) p.isoLo = 0.0;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  p.earlyTermination = 0.999;
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = v == View::AlongPlusZ ? 90.0 : v == View::AlongMinusZ ? -90.0 : 25.0;
  if (v == View::Inside) {  // rays run up and down z from one pixel to the next
    p.camera.elevationDeg = 60.0;
    p.camera.distanceMm = 5.0;
    p.camera.fovDeg = 100.0;
  }
  return p;
}

// The in-core frame of V. Kept for the static tall volume only: a local volume's address comes
// back for the next test's local (a raycaster kept by it drew the ramp of OutOfCorePreview in
// OutOfCoreZarr's "in core" frame, 225 levels off, when the tests ran in one process).
Raycaster& inCore(const Volume& v, bool ess) {
  static std::map<bool, std::unique_ptr<Raycaster>> made;
  static std::unique_ptr<Raycaster> local;
  const bool keep = &v == &tallVolume();
  auto& r = keep ? made[ess] : local;
  if (!r || !keep) {
    r = std::make_unique<Raycaster>(test::pocl(), v, VolumeStorage::Buffer);
    RaycasterOptions o;
    o.emptySpaceSkipping = ess;
    o.packets = false;  // the parts march one ray per work-item, as this does
    r->setOptions(o);
  }
  return *r;
}

int litPixels(const Image& a) {
  int lit = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) lit += a.rgba[i] > 20;
  return lit;
}

OutOfCoreOptions thirdOf(const Volume& v, bool ess = true) {
  OutOfCoreOptions o;
  o.budgetBytes = v.byteSize() / 3;
  o.emptySpaceSkipping = ess;
  o.storage = VolumeStorage::Buffer;
  return o;
}

struct Case {
  Mode mode;
  bool ess;
};

}  // namespace

class OutOfCore : public ::testing::TestWithParam<int> {};
const Case kCases[] = {{Mode::Dvr, true}, {Mode::Dvr, false}, {Mode::Mip, true}, {Mode::Iso, true}};

// A budget of a third of the volume: the converged frame, every view, equals the in-core one.
TEST_P(OutOfCore, ConvergedEqualsInCore) {
  const Case c = kCases[GetParam()];
  const Volume& v = tallVolume();
  auto src = volumeSlabSource(v);
  OutOfCoreRenderer ooc(test::pocl(), *src, thirdOf(v, c.ess));
  // Out of core indeed: more parts than the budget holds, each within it.
  ASSERT_GT(ooc.partCount(), 2);
  EXPECT_LE(ooc.budgetBytes(), v.byteSize() / 3);
  const int fit = int(ooc.budgetBytes() / ooc.partBytesLargest());
  ASSERT_LT(fit, ooc.partCount());
  int worst = 0;
  for (View view : {View::AlongPlusZ, View::AlongMinusZ, View::Oblique, View::Inside}) {
    const RenderParams p = frame(c.mode, view);
    const Image a = inCore(v, c.ess).render(p);
    Image b;
    OutOfCoreStats s;
    ooc.render(p, b, &s);
    EXPECT_TRUE(s.fullResolution) << name(view);
    EXPECT_FALSE(s.deviceOutOfMemory);
    EXPECT_EQ(s.partsCoarse, 0);
    EXPECT_LE(s.partsResident, fit);
    EXPECT_GT(s.uploads, 0) << name(view);
    const int diff = test::maxDiff(a, b);
    EXPECT_LE(diff, 1) << name(view);
    worst = std::max(worst, diff);
    EXPECT_GT(litPixels(a), int(a.rgba.size() / 4 / 50)) << name(view);  // not a blank frame
  }
  std::cout << ooc.partCount() << " parts, " << ooc.residentCount()
            << " resident; largest difference over the views: " << worst << " levels\n";
}

INSTANTIATE_TEST_SUITE_P(Modes, OutOfCore, ::testing::Values(0, 1, 2, 3),
                         [](const ::testing::TestParamInfo<int>& info) {
                           const Case& c = kCases[info.param];
                           return std::string(c.mode == Mode::Dvr   ? "dvr"
                                              : c.mode == Mode::Mip ? "mip"
                                                                    : "iso") +
                                  (c.ess ? "_ess" : "_noess");
                         });

// The storage GPUs use (image3d_t) for the parts and the coarse level, on PoCL.
TEST(OutOfCoreStorage, ImageEqualsInCore) {
  if (!test::pocl().device().imageSupport) GTEST_SKIP() << "no image support";
  const Volume& v = tallVolume();
  auto src = volumeSlabSource(v);
  OutOfCoreOptions o = thirdOf(v);
  o.storage = VolumeStorage::Image3d;
  OutOfCoreRenderer ooc(test::pocl(), *src, o);
  Raycaster one(test::pocl(), v, VolumeStorage::Image3d);
  RaycasterOptions ro;
  ro.packets = false;
  one.setOptions(ro);
  for (Mode mode : {Mode::Dvr, Mode::Iso, Mode::Mip}) {
    const RenderParams p = frame(mode, View::Oblique);
    Image b, pv;
    OutOfCoreStats s;
    ooc.render(p, b, &s);
    EXPECT_TRUE(s.fullResolution);
    EXPECT_LE(test::maxDiff(one.render(p), b), 1) << toString(mode);
    ooc.preview(p, pv, &s);  // the coarse level as an image too
    EXPECT_GT(s.partsCoarse, 0);
    EXPECT_GT(litPixels(pv), int(pv.rgba.size() / 4 / 50));
  }
}

// The same frame again: the part needed latest leaves, so the parts kept are those the next
// frame wants first (and the last one, which it wants before any evicted one comes round):
// it uploads n - k parts (k held), where LRU would upload all n.
TEST(OutOfCoreCache, SecondFrameUploadsOnlyWhatDoesNotFit) {
  const Volume& v = tallVolume();
  auto src = volumeSlabSource(v);
  OutOfCoreOptions o = thirdOf(v);
  o.budgetBytes = v.byteSize() / 2;
  o.partSlices = 4;  // 12-slice parts with their aprons: 3 held at once
  OutOfCoreRenderer ooc(test::pocl(), *src, o);
  const RenderParams p = frame(Mode::Dvr, View::Oblique);
  Image a, b;
  OutOfCoreStats s1, s2;
  ooc.render(p, a, &s1);
  ooc.render(p, b, &s2);
  const int n = ooc.partCount(), k = s1.partsResident;
  ASSERT_GT(k, 1);
  EXPECT_EQ(s1.uploads, n);
  EXPECT_EQ(s2.uploads, n - k);
  EXPECT_EQ(test::maxDiff(a, b), 0);
  EXPECT_LE(test::maxDiff(inCore(v, true).render(p), b), 1);  // several parts held: the same frame
}

// A preview uploads nothing, draws the missing parts from the coarse level and says so; with
// every part held it is the converged frame.
TEST(OutOfCorePreview, CoarseWhereMissingAndFlagged) {
  const Volume& v = tallVolume();
  auto src = volumeSlabSource(v);
  OutOfCoreRenderer ooc(test::pocl(), *src, thirdOf(v));
  const RenderParams p = frame(Mode::Dvr, View::Oblique);
  Image converged, preview;
  OutOfCoreStats s;
  ooc.render(p, converged, &s);
  const int resident = s.partsResident;
  ooc.preview(p, preview, &s);
  EXPECT_FALSE(s.fullResolution);
  EXPECT_EQ(s.uploads, 0);
  EXPECT_EQ(s.partsCoarse, ooc.partCount() - resident);
  EXPECT_EQ(s.partsResident, resident);
  // The coarse level is the same volume a little blurred: near the converged frame on average,
  // not equal to it.
  double sum = 0.0;
  for (size_t i = 0; i < preview.rgba.size(); ++i)
    sum += std::abs(int(preview.rgba[i]) - int(converged.rgba[i]));
  const double mean = sum / double(preview.rgba.size());
  EXPECT_GT(test::maxDiff(preview, converged), 1);
  EXPECT_LT(mean, 12.0);  // 8-bit levels; the 4x box mean moves dvr edges by up to 2 voxels
  std::cout << "preview vs converged: mean " << mean << " levels\n";

  // Everything fits: the preview is the full frame, flagged so.
  OutOfCoreOptions all = thirdOf(v);
  all.budgetBytes = v.byteSize() * 2;
  all.partSlices = 24;
  OutOfCoreRenderer whole(test::pocl(), *src, all);
  Image c2, p2;
  whole.render(p, c2);
  whole.preview(p, p2, &s);
  EXPECT_TRUE(s.fullResolution);
  EXPECT_EQ(s.partsCoarse, 0);
  EXPECT_EQ(test::maxDiff(c2, p2), 0);
}

// The preview differs from the converged frame only where its rays cross a part that is not
// on the device. Seen from the side with parallel rays, each image row lies in one plane z,
// so one part alone draws it; the row's z comes from a mip of a ramp (value 20 z) of the same
// geometry. Rows 2 slices or more inside a held part's own range are the converged frame's
// exactly; rows in the missing parts are drawn coarse, and some differ.
TEST(OutOfCorePreview, DiffersOnlyWhereAPartIsMissing) {
  const Volume& v = tallVolume();
  Volume ramp = v;
  for (int z = 0; z < v.dims.z; ++z)
    for (int i = 0; i < v.dims.x * v.dims.y; ++i)
      ramp.voxels[size_t(z) * size_t(v.dims.x * v.dims.y) + size_t(i)] = int16_t(20 * z);
  RenderParams p = frame(Mode::Dvr, View::Oblique, 64, 96);
  p.camera.elevationDeg = 0.0;
  p.camera.azimuthDeg = 30.0;
  p.camera.projection = Projection::Orthographic;
  RenderParams m = p;
  m.mode = Mode::Mip;
  m.shading = false;
  const Image zImage = inCore(ramp, true).render(m);  // grey = z / 95 (the ramp's range)
  auto src = volumeSlabSource(v);
  OutOfCoreRenderer ooc(test::pocl(), *src, thirdOf(v));
  Image converged, preview;
  OutOfCoreStats s;
  ooc.render(p, converged, &s);
  ooc.preview(p, preview, &s);
  ASSERT_FALSE(s.fullResolution);
  const std::vector<PartRange> ranges = ooc.ranges();
  std::vector<bool> held(ranges.size(), false);
  for (int i : ooc.residentParts()) held[size_t(i)] = true;
  int same = 0, sameLit = 0, inMissing = 0, differ = 0;
  for (size_t px = 0; px < zImage.rgba.size() / 4; ++px) {
    if (zImage.rgba[px * 4] == 0) continue;  // the ray misses the volume (or z < 0.4)
    const double z = zImage.rgba[px * 4] / 255.0 * (v.dims.z - 1);
    int worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst,
                       std::abs(int(preview.rgba[px * 4 + c]) - int(converged.rgba[px * 4 + c])));
    for (size_t k = 0; k < ranges.size(); ++k) {
      if (z < ranges[k].first - 0.5 || z >= ranges[k].end - 0.5) continue;
      const bool inside = z >= ranges[k].first + 2 && z <= ranges[k].end - 3;
      if (held[k] && inside) {
        EXPECT_EQ(worst, 0) << "pixel " << px << " at z " << z << " in held part " << k;
        ++same;
        sameLit += converged.rgba[px * 4] > 20;  // the volume shows there, not the background
      } else if (!held[k] && inside) {
        ++inMissing;
        differ += worst > 1;
      }
    }
  }
  std::cout << same << " pixels in held parts equal (" << sameLit << " lit), " << differ << " of "
            << inMissing << " in missing parts differ\n";
  EXPECT_GT(same, 200);
  EXPECT_GT(sameLit, 50);  // 66 here: the ellipsoid's ends lie in the parts held
  EXPECT_GT(inMissing, 200);
  EXPECT_GT(differ, 0);
}

// A budget below one part: a clear error naming the budget and what to ask for.
TEST(OutOfCoreBudget, TooSmallForOnePartSaysWhatToDo) {
  const Volume& v = tallVolume();
  auto src = volumeSlabSource(v);
  OutOfCoreOptions o;
  o.budgetBytes = size_t(v.dims.x) * v.dims.y * 2 * 12;  // 12 slices: coarse + cells leave < 9
  try {
    OutOfCoreRenderer ooc(test::pocl(), *src, o);
    FAIL() << "a budget of 12 slices was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    const std::string m = e.what();
    EXPECT_NE(m.find("memory budget of"), std::string::npos) << m;
    EXPECT_NE(m.find("raise --memory-budget to at least"), std::string::npos) << m;
    std::cout << m << "\n";
  }
}

// The device fails an allocation mid-frame (it holds 2 parts where the budget says 3): the
// frame completes with the parts it could not take drawn coarse, and says so; the budget
// shrinks to what the device held, and the next frame converges within it.
TEST(OutOfCoreFault, AllocationFailureDropsToCoarse) {
  const Volume& v = tallVolume();
  auto src = volumeSlabSource(v);
  OutOfCoreOptions o = thirdOf(v);
  o.budgetBytes = v.byteSize() / 2;
  o.partSlices = 4;
  o.faultDeviceParts = 2;
  for (Mode mode : {Mode::Dvr, Mode::Iso, Mode::Mip}) {
    OutOfCoreRenderer ooc(test::pocl(), *src, o);
    ASSERT_GE(ooc.budgetBytes() / ooc.partBytesLargest(), 3u);
    const RenderParams p = frame(mode, View::Oblique);
    Image img;
    OutOfCoreStats s;
    ASSERT_NO_THROW(ooc.render(p, img, &s));
    EXPECT_TRUE(s.deviceOutOfMemory);
    EXPECT_FALSE(s.fullResolution);
    EXPECT_NE(s.message.find("coarse level"), std::string::npos) << s.message;
    EXPECT_EQ(s.partsFull + s.partsCoarse, ooc.partCount());
    EXPECT_GT(s.partsCoarse, 0);
    EXPECT_EQ(s.partsResident, 2);
    const Image full = inCore(v, true).render(p);
    double sum = 0.0;
    for (size_t i = 0; i < img.rgba.size(); ++i)
      sum += std::abs(int(img.rgba[i]) - int(full.rgba[i]));
    EXPECT_LT(sum / double(img.rgba.size()), 12.0) << "the coarse parts show the volume";
    // The next frame: within the budget the device held, at full resolution.
    ASSERT_NO_THROW(ooc.render(p, img, &s));
    EXPECT_FALSE(s.deviceOutOfMemory);
    EXPECT_TRUE(s.fullResolution);
    EXPECT_EQ(s.partsFull, ooc.partCount());
    EXPECT_LE(s.partsResident, 2);
    EXPECT_LE(test::maxDiff(full, img), 1);
  }
  // A device that takes no part at all: every frame is the coarse level's, flagged and
  // explained, never an error.
  o.faultDeviceParts = 0;
  OutOfCoreRenderer none(test::pocl(), *src, o);
  for (int frameIndex = 0; frameIndex < 2; ++frameIndex) {
    Image img;
    OutOfCoreStats s;
    ASSERT_NO_THROW(none.render(frame(Mode::Dvr, View::Oblique), img, &s));
    EXPECT_EQ(s.partsCoarse, none.partCount());
    EXPECT_EQ(s.partsResident, 0);
    EXPECT_FALSE(s.fullResolution);
    EXPECT_NE(s.message.find("coarse level"), std::string::npos) << s.message;
    EXPECT_GT(litPixels(img), int(img.rgba.size() / 4 / 50));
  }
}

// The empty-space cells from slices streamed a group at a time equal those of the whole
// volume, bit for bit, for groups that do and do not divide the slices (61: 15 cells and a
// partial one; 37 x 29 partial along x and y too).
TEST(OutOfCoreCells, StreamedEqualWhole) {
  Volume v;
  v.dims = {37, 29, 61};
  v.voxels.resize(v.voxelCount());
  uint32_t seed = 12345;
  for (auto& x : v.voxels) {
    seed = seed * 1664525u + 1013904223u;
    x = int16_t(int(seed >> 16) % 4000 - 1000);
  }
  const MacroCells whole = computeMacroCells(v);
  auto src = volumeSlabSource(v);
  for (int group : {4, 8, 12, 64, 128}) {
    const MacroCells streamed = streamMacroCells(*src, group);
    EXPECT_EQ(streamed.dims, whole.dims);
    EXPECT_TRUE(streamed.minMax == whole.minMax) << "group " << group;
  }
  // A part's complete rows from its slices alone equal the whole's rows: slices [9, 30) hold
  // every voxel of rows 3 to 6 (row c spans slices 4c - 1 to 4c + 4), [0, 61) all 16 rows.
  EXPECT_EQ(completeCellRows(9, 30, 61), glm::ivec2(3, 7));
  EXPECT_EQ(completeCellRows(0, 61, 61), glm::ivec2(0, 16));
  EXPECT_EQ(completeCellRows(55, 61, 61), glm::ivec2(14, 16));  // the last row ends at 60
  EXPECT_EQ(completeCellRows(10, 14, 61), glm::ivec2(0, 0));    // no row fits in 4 slices
  const size_t slice = size_t(v.dims.x) * v.dims.y, row = size_t(whole.dims.x) * whole.dims.y * 2;
  for (glm::ivec2 range : {glm::ivec2(9, 30), glm::ivec2(0, 61), glm::ivec2(55, 61)}) {
    const glm::ivec2 rows = completeCellRows(range.x, range.y, v.dims.z);
    const std::vector<int16_t> part =
        computeMacroCellRows(v.voxels.data() + size_t(range.x) * slice, range.x, v.dims, rows);
    EXPECT_TRUE(std::equal(part.begin(), part.end(), whole.minMax.begin() + rows.x * row))
        << range.x << " to " << range.y;
    EXPECT_EQ(part.size(), size_t(rows.y - rows.x) * row);
  }
}

// A raw file read with pread a range of slices at a time: the converged frame equals the one
// from the same file loaded whole (importRaw), bit for bit, for a layout whose storage needs no
// look at the values (big-endian i16 as it is: no pass before the first image but the coarse
// level's) and for one that needs the values (an intercept that could leave int16: the reader
// scans them first, as importRaw does, and stores them alike). A folder of slice files too.
TEST(OutOfCoreRaw, ReadOnDemandEqualsLoadedWhole) {
  const Volume& v = tallVolume();
  const auto dir =
      std::filesystem::temp_directory_path() / ("voxray-ooc-raw-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "slices");
  const size_t slice = size_t(v.dims.x) * v.dims.y;
  std::vector<uint8_t> bytes(v.voxels.size() * 2);
  for (size_t i = 0; i < v.voxels.size(); ++i) {  // big endian
    bytes[2 * i] = uint8_t(uint16_t(v.voxels[i]) >> 8);
    bytes[2 * i + 1] = uint8_t(uint16_t(v.voxels[i]) & 0xff);
  }
  const std::string file = (dir / "tall.raw").string();
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  for (int z = 0; z < v.dims.z; ++z)
    std::ofstream((dir / "slices" / ("s." + std::to_string(z + 1))).string(), std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data() + size_t(z) * slice * 2),
               std::streamsize(slice * 2));
  RawLayout layout;
  layout.dims = v.dims;
  layout.order = ByteOrder::Big;
  layout.spacingMm = v.spacingMm;
  RawLayout shifted = layout;  // -32768 - 1024 would not fit int16: the values decide
  shifted.intercept = -1024.0;
  RawLayout stack = layout;
  stack.dims.z = 0;  // every file of the folder
  struct Input {
    std::string path;
    RawLayout layout;
    bool scanned;
  };
  const RenderParams p = frame(Mode::Dvr, View::Oblique);
  for (const Input& in : {Input{file, layout, false}, Input{file, shifted, true},
                          Input{(dir / "slices").string(), stack, false}}) {
    const Volume whole = importRaw(in.path, in.layout);
    EXPECT_EQ(RawSliceReader(in.path, in.layout).scanned(), in.scanned) << in.path;
    auto raw = rawSlabSource(in.path, in.layout);
    auto mem = volumeSlabSource(whole);
    const Volume& g = raw->geometry();
    EXPECT_EQ(g.dims, whole.dims);
    EXPECT_EQ(g.slope, whole.slope);
    EXPECT_EQ(g.intercept, whole.intercept);
    EXPECT_EQ(g.unit, whole.unit);
    std::vector<int16_t> part(slice * 21);
    raw->readSlices(40, 61, part.data());
    EXPECT_TRUE(std::equal(part.begin(), part.end(), whole.voxels.begin() + 40 * slice));
    OutOfCoreRenderer a(test::pocl(), *raw, thirdOf(v)), b(test::pocl(), *mem, thirdOf(v));
    ASSERT_GT(a.partCount(), 2);
    EXPECT_EQ(a.ranges().size(), b.ranges().size()) << "the same plan, whichever level is shown";
    // No pass before the first image (the quick level is on the device); the first converged
    // frame waits for the coarse level's pass, which found the exact range: it is not redrawn.
    EXPECT_FALSE(raw->statedRange().has_value());
    for (Mode mode : {Mode::Dvr, Mode::Mip}) {
      RenderParams q = frame(mode, View::Oblique);
      Image ia, ib;
      OutOfCoreStats s;
      a.render(q, ia, &s);
      EXPECT_FALSE(s.redrawnForRange);
      EXPECT_EQ(s.shown, "full");
      ASSERT_TRUE(raw->statedRange().has_value());
      EXPECT_EQ(raw->statedRange()->min, storedRange(whole).min);
      EXPECT_EQ(raw->statedRange()->max, storedRange(whole).max);
      b.render(q, ib);
      EXPECT_EQ(test::maxDiff(ia, ib), 0) << in.path << " " << toString(mode);
      EXPECT_GT(litPixels(ia), int(ia.rgba.size() / 4 / 50));
    }
  }
  EXPECT_THROW(rawSlabSource((dir / "missing.raw").string(), layout), Error);
  std::filesystem::remove_all(dir);
}

// A raw file's first image is drawn before the coarse level's pass over the file: from the
// quick level, point samples (each the voxel nearest its cell's centre, exactly), and says
// "preview"; the pass starts after it. Once the pass is done the previews are the coarse
// level's, equal bit for bit to an in-memory source's (the same 4x mean, range and cells), and
// the converged frame equals the loaded volume's bit for bit (tolerance 0: the same parts, the
// same slices, the same range; the quick level changes neither).
TEST(OutOfCoreRaw, FirstImageFromPointSamplesBeforeThePass) {
  const Volume& v = tallVolume();
  const auto dir =
      std::filesystem::temp_directory_path() / ("voxray-ooc-quick-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "tall.raw").string();
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(v.voxels.data()), std::streamsize(v.byteSize()));
  RawLayout layout;
  layout.dims = v.dims;
  layout.spacingMm = v.spacingMm;
  auto raw = rawSlabSource(file, layout);
  auto mem = volumeSlabSource(v);
  // 40x36x96 has 138240 voxels: under kQuickVoxels at 4x, so the quick level has the coarse
  // level's dims, and its voxels are samples of the volume, not means.
  const Volume* quick = raw->quickLevel();
  ASSERT_NE(quick, nullptr);
  const Volume& coarse = mem->coarse();
  EXPECT_EQ(quick->dims, coarse.dims);
  EXPECT_EQ(quick->originMm, coarse.originMm);
  EXPECT_EQ(quick->spacingMm, coarse.spacingMm);
  int differ = 0;
  for (int k = 0; k < quick->dims.z; ++k)
    for (int j = 0; j < quick->dims.y; ++j)
      for (int i = 0; i < quick->dims.x; ++i) {
        auto near = [](int c, int n, int cn) {  // the full voxel nearest coarse voxel c's centre
          return std::clamp(int(std::lround((c + 0.5) * n / cn - 0.5)), 0, n - 1);
        };
        const int x = near(i, v.dims.x, quick->dims.x), y = near(j, v.dims.y, quick->dims.y),
                  z = near(k, v.dims.z, quick->dims.z);
        ASSERT_EQ(quick->voxels[quick->index(i, j, k)], v.voxels[v.index(x, y, z)])
            << i << "," << j << "," << k;
        differ += quick->voxels[quick->index(i, j, k)] != coarse.voxels[coarse.index(i, j, k)];
      }
  EXPECT_GT(differ, 0) << "samples, not the means";
  OutOfCoreRenderer a(test::pocl(), *raw, thirdOf(v)), b(test::pocl(), *mem, thirdOf(v));
  EXPECT_FALSE(raw->coarseReady()) << "no pass before the first image";
  const RenderParams p = frame(Mode::Dvr, View::Oblique);
  Image first, coarseA, coarseB, fullA, fullB;
  OutOfCoreStats s;
  a.preview(p, first, &s);
  EXPECT_EQ(s.shown, "preview");
  EXPECT_EQ(s.partsCoarse, a.partCount());
  EXPECT_EQ(s.cellsKnown, 0.0);
  EXPECT_GT(litPixels(first), int(first.rgba.size() / 4 / 50));
  raw->coarse();  // the pass the first preview started, waited for
  EXPECT_TRUE(raw->coarseReady());
  a.preview(p, coarseA, &s);
  EXPECT_EQ(s.shown, "coarse");
  b.preview(p, coarseB, &s);
  EXPECT_EQ(s.shown, "coarse");
  EXPECT_EQ(test::maxDiff(coarseA, coarseB), 0);
  EXPECT_GT(test::maxDiff(first, coarseA), 0) << "the preview was the samples'";
  a.render(p, fullA, &s);
  EXPECT_EQ(s.shown, "full");
  EXPECT_FALSE(s.redrawnForRange);
  b.render(p, fullB);
  EXPECT_EQ(test::maxDiff(fullA, fullB), 0);
  std::filesystem::remove_all(dir);
}

#ifdef VOXRAY_HAS_ZARR
// Slices read on demand from an OME-Zarr level: a range equals the level's slices, and the
// converged frame equals the in-core frame of the same Zarr.
TEST(OutOfCoreZarr, StreamedEqualsInCore) {
  const Volume& v = tallVolume();
  const auto dir = std::filesystem::temp_directory_path() /
                   ("voxray-ooc-" + std::to_string(::getpid()) + ".ome.zarr");
  std::filesystem::remove_all(dir);
  ZarrWriteOptions w;
  w.chunk = 16;
  writeOmeZarr(v, dir.string(), w);
  const Volume whole = importOmeZarr(dir.string());
  {
    auto store = zarrFolderStore(dir.string());
    OmeZarrLevel level(*store, 0);
    EXPECT_EQ(level.geometry().dims, v.dims);
    EXPECT_EQ(level.chunkSlices(), 16);
    const size_t slice = size_t(v.dims.x) * v.dims.y;
    std::vector<int16_t> part(slice * 21);
    level.readSlices(30, 51, part.data());  // across two chunk boundaries
    EXPECT_TRUE(std::equal(part.begin(), part.end(), whole.voxels.begin() + 30 * slice));
    // 3 chunk rows of 3x3 chunks (x 40, y 36 in 16s), no more.
    EXPECT_EQ(level.chunksRead(), 27u);
  }
  auto src = omeZarrSlabSource(dir.string());
  OutOfCoreRenderer ooc(test::pocl(), *src, thirdOf(v));
  ASSERT_GT(ooc.partCount(), 2);
  for (Mode mode : {Mode::Dvr, Mode::Iso}) {
    const RenderParams p = frame(mode, View::Oblique);
    Image b;
    ooc.render(p, b);
    EXPECT_LE(test::maxDiff(inCore(whole, true).render(p), b), 1);
  }
  std::filesystem::remove_all(dir);
}

namespace {

std::filesystem::path tempZarr(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("voxray-ooc-" + name + "-" + std::to_string(::getpid()) + ".ome.zarr");
  std::filesystem::remove_all(dir);
  ZarrWriteOptions w;
  w.chunk = 16;
  writeOmeZarr(tallVolume(), dir.string(), w);
  return dir;
}

// Replaces the "level0-range" entry of DIR's group attributes with TEXT ("" removes it).
void setStatedRange(const std::filesystem::path& dir, const std::string& text) {
  const auto file = dir / ".zattrs";
  std::stringstream in;
  in << std::ifstream(file).rdbuf();
  const std::string before = in.str();
  const std::regex entry(R"re(,?\s*"level0-range"\s*:\s*(\[[^\]]*\]|"[^"]*"))re");
  if (!std::regex_search(before, entry)) throw std::runtime_error("no level0-range in " + before);
  const std::string after =
      std::regex_replace(before, entry, text.empty() ? "" : ", \"level0-range\": " + text);
  std::ofstream(file) << after;
}

}  // namespace

// The first image reads no full-resolution slice, and the converged frame is the in-core one
// whatever the Zarr states of its range: the range convert writes (used from the first frame,
// not drawn again), none (the coarse level's range, narrower, widened as the parts arrive:
// the first converged frame is drawn again), a wrong one (replaced by the voxels', and said),
// a damaged one (ignored, with a warning). The frames of all four are equal, bit for bit.
TEST(OutOfCoreZarr, NoPassBeforeTheFirstImageAndTheSameConvergedFrame) {
  const Volume& v = tallVolume();
  const auto dir = tempZarr("range");
  const Volume whole = importOmeZarr(dir.string());
  const ValueRange exact = storedRange(whole);
  const RenderParams p = frame(Mode::Dvr, View::Oblique);
  const Image inCoreFrame = inCore(whole, true).render(p);
  std::vector<Image> converged;
  for (const std::string stated : {"written", "[0, 10]", "\"wide\"", ""}) {
    if (stated != "written") setStatedRange(dir, stated);
    auto src = omeZarrSlabSource(dir.string());
    if (stated == "written") {
      ASSERT_TRUE(src->statedRange().has_value());
      EXPECT_EQ(src->statedRange()->min, exact.min);
      EXPECT_EQ(src->statedRange()->max, exact.max);
    }
    bool warned = false;
    for (const std::string& w : src->geometry().warnings)
      warned = warned || w.find("level0-range") != std::string::npos;
    EXPECT_EQ(warned, stated == "\"wide\"") << stated;
    OutOfCoreRenderer ooc(test::pocl(), *src, thirdOf(v));
    Image first, b;
    OutOfCoreStats s;
    ooc.preview(p, first, &s);  // the first image: from the coarse level, no part read
    EXPECT_EQ(s.partsCoarse, ooc.partCount());
    EXPECT_EQ(s.cellsKnown, 0.0);
    EXPECT_GT(litPixels(first), int(first.rgba.size() / 4 / 50)) << stated;
    ooc.render(p, b, &s);
    EXPECT_TRUE(s.fullResolution);
    EXPECT_EQ(s.cellsKnown, 1.0);
    EXPECT_EQ(s.redrawnForRange, stated != "written") << stated;
    EXPECT_EQ(s.note.find("is not its voxels'") != std::string::npos, stated == "[0, 10]")
        << stated << ": " << s.note;
    EXPECT_LE(test::maxDiff(inCoreFrame, b), 1) << stated;
    // The next frame: the cells made from the voxels, the range settled; nothing drawn twice.
    Image again;
    ooc.render(frame(Mode::Dvr, View::AlongMinusZ), again, &s);
    EXPECT_FALSE(s.redrawnForRange);
    EXPECT_LE(test::maxDiff(inCore(whole, true).render(frame(Mode::Dvr, View::AlongMinusZ)), again),
              1)
        << stated;
    converged.push_back(b);
  }
  for (size_t i = 1; i < converged.size(); ++i)
    EXPECT_EQ(test::maxDiff(converged[0], converged[i]), 0) << i;
  std::filesystem::remove_all(dir);
}

// Missing level-0 chunks: the first image still comes (it reads none of them), the converged
// frame draws them empty, as the in-core reader's fill value does, and says how many.
TEST(OutOfCoreZarr, MissingChunksDrawnEmptyAndSaid) {
  const auto dir = tempZarr("missing");
  // Chunk (z 2, y 1, x 1) of level 0: slices 32-47, across the ellipsoid's middle.
  ASSERT_TRUE(std::filesystem::remove(dir / "0" / "2" / "1" / "1"))
      << "the chunk key layout changed";
  const Volume whole = importOmeZarr(dir.string());  // reads it as the fill value, with a warning
  auto src = omeZarrSlabSource(dir.string());
  OutOfCoreRenderer ooc(test::pocl(), *src, thirdOf(tallVolume()));
  const RenderParams p = frame(Mode::Dvr, View::Oblique);
  Image b;
  OutOfCoreStats s;
  ooc.preview(p, b, &s);
  EXPECT_EQ(s.missingChunks, 0u);
  EXPECT_TRUE(s.note.empty()) << s.note;
  ooc.render(p, b, &s);
  EXPECT_EQ(s.missingChunks, 1u);
  EXPECT_NE(s.note.find("1 chunks of the volume were missing"), std::string::npos) << s.note;
  EXPECT_LE(test::maxDiff(inCore(whole, true).render(p), b), 1);
  // Not the complete volume's frame: the hole shows.
  EXPECT_GT(test::maxDiff(inCore(tallVolume(), true).render(p), b), 8);
  std::filesystem::remove_all(dir);
}
#endif

}  // namespace voxray
