// Voxray writes an OME-Zarr pyramid and reads it back: voxel for voxel, geometry within 1e-6
// mm, for Zarr v2 and v3 and each codec; the coarser levels are the 2x2x2 means.
#include <filesystem>
#include <tuple>

#include "voxray/io/load.h"
#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/dicom_import.h"
#endif
#include "zarr_test_support.h"

namespace fs = std::filesystem;

namespace voxray::test {
namespace {

using Case = std::tuple<int, ZarrCodec>;

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  static const char* const names[] = {"BloscZstd", "Zstd", "Gzip", "None"};
  return "V" + std::to_string(std::get<0>(info.param)) + names[int(std::get<1>(info.param))];
}

class OmeZarrRoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(OmeZarrRoundTrip, GivesEveryVoxelAndTheGeometryBackAndTheMeansAtEachLevel) {
  const auto [version, codec] = GetParam();
  TempDir dir;
  const Volume v = zarrTestVolume();
  ZarrWriteOptions o;
  o.zarrVersion = version;
  o.codec = codec;
  o.chunk = 16;
  o.levels = 3;
  const std::string path = dir.file("v.ome.zarr");
  const ZarrWriteResult r = writeOmeZarr(v, path, o);
  ASSERT_EQ(r.dims.size(), 3u);
  EXPECT_EQ(r.dims[1], glm::ivec3(23, 19, 15));  // odd sizes round up
  EXPECT_EQ(r.dims[2], glm::ivec3(12, 10, 8));
  EXPECT_EQ(r.dataType, "int16");
  // 3 x 3 x 2 + 2 x 2 x 1 + 1 chunks of 16^3 (the last level's chunk is its size).
  EXPECT_EQ(r.chunks, 18u + 4u + 1u);

  const Volume back = loadVolume(path);  // the workstation's and the CLI's path
  ASSERT_EQ(back.dims, v.dims);
  EXPECT_EQ(back.slope, 1.0);
  EXPECT_EQ(back.intercept, 0.0);
  EXPECT_TRUE(back.voxels == std::vector<int16_t>(v.voxels.begin(), v.voxels.end()));
  expectNear(back.spacingMm, v.spacingMm, "spacing");
  expectNear(back.originMm, v.originMm, "origin");
  for (int c = 0; c < 3; ++c) expectNear(back.direction[c], v.direction[c], "direction");
  EXPECT_EQ(back.unit, "HU");
  EXPECT_EQ(back.modality, "CT");
  EXPECT_TRUE(back.warnings.empty()) << back.warnings.front();

  Volume previous = back;
  for (int level = 1; level < 3; ++level) {
    LoadOptions lo;
    lo.level = level;
    const Volume l = loadVolume(path, lo);
    ASSERT_EQ(l.dims, r.dims[size_t(level)]);
    size_t wrong = 0;
    for (int z = 0; z < l.dims.z; ++z)
      for (int y = 0; y < l.dims.y; ++y)
        for (int x = 0; x < l.dims.x; ++x)
          wrong += l.toPhysical(l.at(x, y, z)) != halvedValue(previous, x, y, z);
    EXPECT_EQ(wrong, 0u) << "level " << level;
    // Spacing doubles; voxel 0's centre moves to the middle of the 2x2x2 block it averages.
    expectNear(l.spacingMm, previous.spacingMm * 2.0, "level spacing");
    expectNear(l.originMm, previous.originMm + previous.direction * (previous.spacingMm / 2.0),
               "level origin");
    previous = l;
  }
}

INSTANTIATE_TEST_SUITE_P(VersionsAndCodecs, OmeZarrRoundTrip,
                         ::testing::Combine(::testing::Values(2, 3),
                                            ::testing::Values(ZarrCodec::BloscZstd, ZarrCodec::Zstd,
                                                              ZarrCodec::Gzip, ZarrCodec::None)),
                         caseName);

TEST(OmeZarrWrite, FractionalValuesAreWrittenAsFloat32AndReadBackWithinTheirStep) {
  TempDir dir;
  Volume v = zarrTestVolume();
  v.slope = 0.25;  // a PET or a rescaled MR: values are not whole numbers
  v.intercept = -0.5;
  const std::string path = dir.file("f.ome.zarr");
  ZarrWriteOptions o;
  o.zarrVersion = 3;
  o.chunk = 32;
  EXPECT_EQ(writeOmeZarr(v, path, o).dataType, "float32");
  const Volume back = loadVolume(path);
  ASSERT_EQ(back.dims, v.dims);
  EXPECT_EQ(back.sourceType, "f32");
  // The values are multiples of 0.25 (exact in float32); read back they are stored with the
  // step raw input chooses (a power of two over their range), so within half of it.
  double worst = 0;
  for (size_t i = 0; i < v.voxelCount(); ++i)
    worst = std::max(worst, std::abs(back.toPhysical(back.voxels[i]) - v.toPhysical(v.voxels[i])));
  EXPECT_LE(worst, back.slope / 2 + 1e-9);
  EXPECT_LE(back.slope, 0.25);
}

TEST(OmeZarrWrite, RefusesAnExistingOutputUnlessForcedAndLeavesNoPartialFolder) {
  TempDir dir;
  const Volume v = zarrTestVolume();
  const std::string path = dir.file("v.ome.zarr");
  fs::create_directories(path);
  const std::string message = errorMessage([&] { writeOmeZarr(v, path); }, Error::Kind::Output);
  EXPECT_THAT(message,
              ::testing::HasSubstr("exists already; choose another name, or give --force"));
  ZarrWriteOptions o;
  o.force = true;
  writeOmeZarr(v, path, o);
  EXPECT_EQ(loadVolume(path).dims, v.dims);
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "v.ome.zarr");  // no .partial-PID or .replaced-PID left
  }
  EXPECT_EQ(entries, 1u);
}

TEST(OmeZarrWrite, DefaultLevelsHalveUntilOneChunkHoldsASlice) {
  TempDir dir;
  const Volume v = zarrTestVolume();  // 45 x 38: 45 -> 23 -> 12 <= 16
  ZarrWriteOptions o;
  o.chunk = 16;
  const ZarrWriteResult r = writeOmeZarr(v, dir.file("v.ome.zarr"), o);
  ASSERT_EQ(r.dims.size(), 3u);
  EXPECT_EQ(r.dims.back(), glm::ivec3(12, 10, 8));
}

TEST(OmeZarrRead, AMissingChunkReadsAsTheFillValueWithAWarningSayingHowMany) {
  TempDir dir;
  const Volume v = zarrTestVolume();
  const std::string path = dir.file("v.ome.zarr");
  ZarrWriteOptions o;
  o.zarrVersion = 3;
  o.chunk = 16;
  o.levels = 1;
  writeOmeZarr(v, path, o);
  // Chunk (z 1, y 0, x 2): voxels x 32..44, y 0..15, z 16..28.
  ASSERT_TRUE(fs::remove(fs::path(path) / "0" / "c" / "1" / "0" / "2"));
  const Volume back = loadVolume(path);
  ASSERT_EQ(back.warnings.size(), 1u);
  EXPECT_THAT(back.warnings[0], ::testing::HasSubstr("1 of 18 chunks are missing"));
  EXPECT_THAT(back.warnings[0], ::testing::HasSubstr("fill value 0"));
  size_t zeros = 0, wrong = 0;
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        const bool missing = x >= 32 && y < 16 && z >= 16;
        const int16_t expected = missing ? 0 : v.at(x, y, z);
        wrong += back.at(x, y, z) != expected;
        zeros += missing;
      }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(zeros, size_t(13 * 16 * 13));
}

TEST(OmeZarrRead, AFolderWithATrailingSlashOpensAsWell) {
  TempDir dir;
  const Volume v = zarrTestVolume();
  const std::string path = dir.file("v.ome.zarr");
  writeOmeZarr(v, path);
  EXPECT_TRUE(isOmeZarr(path + "/"));
  EXPECT_EQ(loadVolume(path + "/").dims, v.dims);
#ifdef VOXRAY_HAS_DICOM
  // File > Open DICOM folder lists series first: it says what the folder is instead.
  EXPECT_THAT(errorMessage([&] { listDicomSeries(path); }),
              ::testing::HasSubstr("is an OME-Zarr folder, not DICOM; open it as it is"));
#endif
  // The workstation's loader reads every time point: an OME-Zarr has one.
  const std::vector<Volume> series = loadVolumeSeries(path);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].dims, v.dims);
}

}  // namespace
}  // namespace voxray::test
