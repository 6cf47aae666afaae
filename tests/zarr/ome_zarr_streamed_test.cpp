// voxray-cli convert's streamed path (issue 38): the pyramid written from a SliceSource read a
// slab at a time is the one written from the same volume loaded whole, byte for byte in every
// file (chunks and metadata), for Zarr v2 and v3, odd sizes, raw types whose storage needs no
// look at the values and ones whose storage comes from the reader's one scan; and level 0's
// recorded value range is exact.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

#include "voxray/io/load.h"
#include "voxray/io/slice_source.h"
#include "zarr_test_support.h"

namespace fs = std::filesystem;

namespace voxray::test {
namespace {

// Every file below ROOT by its relative path, with its bytes.
std::map<std::string, std::string> filesOf(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    files[fs::relative(e.path(), root).string()] =
        std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return files;
}

// Whether the two pyramids hold the same files with the same bytes; what differs in WHY.
bool sameFiles(const fs::path& a, const fs::path& b, std::string& why) {
  const auto fa = filesOf(a), fb = filesOf(b);
  for (const auto& [name, bytes] : fa) {
    const auto it = fb.find(name);
    if (it == fb.end()) {
      why = name + " is missing in the streamed pyramid";
      return false;
    }
    if (it->second != bytes) {
      why = name + " differs (" + std::to_string(bytes.size()) + " vs " +
            std::to_string(it->second.size()) + " bytes)";
      return false;
    }
  }
  if (fa.size() != fb.size()) {
    why = std::to_string(fb.size()) + " files streamed against " + std::to_string(fa.size());
    return false;
  }
  why = std::to_string(fa.size()) + " files";
  return true;
}

// Raw inputs: 45 columns, 37 rows (odd), 29 slices (odd); chunks of 16 make edge chunks on
// every axis and odd sizes on the levels below.
constexpr int kX = 45, kY = 37, kZ = 29;

enum class RawCase {
  I16,        // HU as they are: int16 without a look at the values
  I16Shift,   // i16 with --raw-rescale 1,-1024: the one scan finds they fit, int16
  U16Wide,    // u16 0..60000: slope 1, intercept 32768 after the scan; float32
  F32Quarter  // f32 in quarters: a fine slope after the scan; float32
};

struct Input {
  RawLayout layout;
  std::vector<uint8_t> bytes;
};

Input rawInput(RawCase c) {
  Input in;
  in.layout.dims = {kX, kY, kZ};
  in.layout.spacingMm = {0.7, 0.8, 1.3};
  in.layout.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, -1));
  const size_t n = size_t(kX) * kY * kZ;
  auto put = [&](const auto& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    in.bytes.insert(in.bytes.end(), p, p + sizeof value);
  };
  for (size_t i = 0; i < n; ++i) {
    const int a = int((i * 71 + i / kX * 13 + i / (size_t(kX) * kY) * 131) % 3001);
    switch (c) {
      case RawCase::I16:
        in.layout.type = SampleType::I16;
        put(int16_t(a - 1024));
        break;
      case RawCase::I16Shift:
        in.layout.type = SampleType::I16;
        in.layout.intercept = -1024;
        put(int16_t(a));
        break;
      case RawCase::U16Wide:
        in.layout.type = SampleType::U16;
        put(uint16_t(a * 20));
        break;
      case RawCase::F32Quarter:
        in.layout.type = SampleType::F32;
        put(float(a) * 0.25f - 200.0f);
        break;
    }
  }
  return in;
}

using StreamedConvertCase = std::tuple<int, RawCase>;

std::string streamedConvertName(const ::testing::TestParamInfo<StreamedConvertCase>& info) {
  static const char* const names[] = {"I16", "I16Shift", "U16Wide", "F32Quarter"};
  return "V" + std::to_string(std::get<0>(info.param)) + names[int(std::get<1>(info.param))];
}

class StreamedConvert : public ::testing::TestWithParam<StreamedConvertCase> {};

TEST_P(StreamedConvert, RawStreamedEqualsLoadedWholeByteForByte) {
  const auto [version, rawCase] = GetParam();
  TempDir dir;
  const Input in = rawInput(rawCase);
  const std::string raw = dir.file("in.raw");
  writeBytes(raw, in.bytes);
  ZarrWriteOptions o;
  o.zarrVersion = version;
  o.chunk = 16;

  LoadOptions lo;
  lo.raw = in.layout;
  const Volume whole = loadVolume(raw, lo);
  const ZarrWriteResult a = writeOmeZarr(whole, dir.file("whole.ome.zarr"), o);
  const std::unique_ptr<SliceSource> source = rawSliceSource(raw, in.layout);
  EXPECT_EQ(source->slicesInPlace(0), nullptr);  // read from the file, slab by slab
  const ZarrWriteResult b = writeOmeZarr(*source, dir.file("streamed.ome.zarr"), o);

  // The type each case is there for: int16 when the values are whole and fit, else float32.
  const bool int16 = rawCase == RawCase::I16 || rawCase == RawCase::I16Shift;
  EXPECT_EQ(a.dataType, int16 ? "int16" : "float32");
  EXPECT_EQ(b.dataType, a.dataType);
  ASSERT_EQ(b.dims.size(), 3u);  // 45 -> 23 -> 12: one chunk holds a slice
  EXPECT_EQ(b.dims, a.dims);
  EXPECT_EQ(b.dims[1], glm::ivec3(23, 19, 15));
  EXPECT_EQ(b.chunks, a.chunks);
  EXPECT_EQ(b.bytes, a.bytes);
  std::string why;
  EXPECT_TRUE(sameFiles(dir.path() / "whole.ome.zarr", dir.path() / "streamed.ome.zarr", why))
      << why;
}

INSTANTIATE_TEST_SUITE_P(VersionsAndTypes, StreamedConvert,
                         ::testing::Combine(::testing::Values(2, 3),
                                            ::testing::Values(RawCase::I16, RawCase::I16Shift,
                                                              RawCase::U16Wide,
                                                              RawCase::F32Quarter)),
                         streamedConvertName);

// The range recorded in the metadata (out-of-core rendering maps its colour table with it) is
// level 0's exact smallest and largest value: here -1024 and 1976 (a = 0 and a = 3000 occur).
TEST(StreamedConvert, RecordsLevel0sExactRange) {
  TempDir dir;
  const Input in = rawInput(RawCase::I16Shift);
  const std::string raw = dir.file("in.raw");
  writeBytes(raw, in.bytes);
  const std::unique_ptr<SliceSource> source = rawSliceSource(raw, in.layout);
  ZarrWriteOptions o;
  o.chunk = 16;
  writeOmeZarr(*source, dir.file("v.ome.zarr"), o);
  std::ifstream attrs(dir.file("v.ome.zarr/.zattrs"));
  const auto j = nlohmann::json::parse(attrs);
  const Volume back = loadVolume(dir.file("v.ome.zarr"));
  const auto [lo, hi] = std::minmax_element(back.voxels.begin(), back.voxels.end());
  EXPECT_EQ(*lo, -1024);
  EXPECT_EQ(*hi, 1976);
  EXPECT_EQ(j.at("voxray").at("level0-range"), nlohmann::json({-1024, 1976}));
}

// The raw reader's one scan gives the stored range the writer needs for a non-zero intercept:
// exactly that of the voxels importRaw stores (u16 beyond int16; f32 with NaN and infinity,
// stored as the lowest value).
TEST(StreamedConvert, RawScanGivesTheStoredRange) {
  TempDir dir;
  for (RawCase c : {RawCase::U16Wide, RawCase::F32Quarter}) {
    Input in = rawInput(c);
    if (c == RawCase::F32Quarter) {
      const float bad[] = {NAN, INFINITY};
      std::memcpy(in.bytes.data() + 4 * 100, &bad[0], 4);
      std::memcpy(in.bytes.data() + 4 * 7000, &bad[1], 4);
    }
    const std::string raw = dir.file("in.raw");
    writeBytes(raw, in.bytes);
    const RawSliceReader reader(raw, in.layout);
    ASSERT_TRUE(reader.scanned());
    const std::optional<ValueRange> r = reader.storedRange();
    ASSERT_TRUE(r.has_value());
    const ValueRange truth = storedRange(importRaw(raw, in.layout));
    EXPECT_EQ(r->min, truth.min);
    EXPECT_EQ(r->max, truth.max);
    // And the source writes it as a whole volume does (the range decides int16 or float32).
    ZarrWriteOptions o;
    o.chunk = 16;
    const std::unique_ptr<SliceSource> source = rawSliceSource(raw, in.layout);
    writeOmeZarr(*source, dir.file("s.ome.zarr"), o);
    writeOmeZarr(importRaw(raw, in.layout), dir.file("w.ome.zarr"), o);
    std::string why;
    EXPECT_TRUE(sameFiles(dir.path() / "w.ome.zarr", dir.path() / "s.ome.zarr", why)) << why;
    fs::remove_all(dir.path() / "s.ome.zarr");
    fs::remove_all(dir.path() / "w.ome.zarr");
  }
}

// A source that knows no range and holds nothing in place: a whole intercept other than 0 makes
// the writer read the slices once more for the range. 31000 + values up to 1975 pass int16:
// float32; 1000 + them fit: int16. Either way the bytes are the whole volume's.
class UnrangedSource : public SliceSource {
 public:
  explicit UnrangedSource(const Volume& v) : inner_(volumeSliceSource(v)) {}
  const Volume& geometry() const override { return inner_->geometry(); }
  void readSlices(int first, int end, int16_t* dest) override {
    ++reads;
    inner_->readSlices(first, end, dest);
  }
  int reads = 0;

 private:
  std::unique_ptr<SliceSource> inner_;
};

TEST(StreamedConvert, UnknownRangeTakesOnePassMore) {
  TempDir dir;
  for (double intercept : {31000.0, 1000.0}) {
    Volume v = zarrTestVolume();  // 45 x 38 x 29, stored -1024..1975
    v.intercept = intercept;
    ZarrWriteOptions o;
    o.zarrVersion = 3;
    o.chunk = 16;
    UnrangedSource source(v);
    const ZarrWriteResult s = writeOmeZarr(source, dir.file("s.ome.zarr"), o);
    EXPECT_EQ(source.reads, 2 * 2) << "two slabs of 16 slices, read for the range and to write";
    const ZarrWriteResult w = writeOmeZarr(v, dir.file("w.ome.zarr"), o);
    EXPECT_EQ(s.dataType, intercept == 1000.0 ? "int16" : "float32");
    EXPECT_EQ(w.dataType, s.dataType);
    std::string why;
    EXPECT_TRUE(sameFiles(dir.path() / "w.ome.zarr", dir.path() / "s.ome.zarr", why)) << why;
    fs::remove_all(dir.path() / "s.ome.zarr");
    fs::remove_all(dir.path() / "w.ome.zarr");
  }
}

// An OME-Zarr level read a chunk row at a time writes what the same level loaded whole writes,
// its chunks (of 16 slices) read as the writer's slabs (of 8) need them.
TEST(StreamedConvert, ZarrStreamedEqualsLoadedWhole) {
  TempDir dir;
  ZarrWriteOptions o;
  o.chunk = 16;
  writeOmeZarr(zarrTestVolume(), dir.file("in.ome.zarr"), o);
  for (int level : {0, 1}) {
    std::unique_ptr<SliceSource> source =
        omeZarrSliceSource(zarrFolderStore(dir.file("in.ome.zarr")), level);
    ASSERT_NE(source, nullptr);
    ZarrWriteOptions w;
    w.zarrVersion = 3;
    w.chunk = 8;
    writeOmeZarr(*source, dir.file("s.ome.zarr"), w);
    LoadOptions lo;
    lo.level = level;
    writeOmeZarr(loadVolume(dir.file("in.ome.zarr"), lo), dir.file("w.ome.zarr"), w);
    std::string why;
    EXPECT_TRUE(sameFiles(dir.path() / "w.ome.zarr", dir.path() / "s.ome.zarr", why))
        << "level " << level << ": " << why;
    EXPECT_TRUE(source->warnings().empty());
    fs::remove_all(dir.path() / "s.ome.zarr");
    fs::remove_all(dir.path() / "w.ome.zarr");
  }
}

// A missing chunk streams as the fill value, as a whole load reads it, and the source says so.
TEST(StreamedConvert, MissingZarrChunkSaid) {
  TempDir dir;
  ZarrWriteOptions o;
  o.chunk = 16;
  writeOmeZarr(zarrTestVolume(), dir.file("in.ome.zarr"), o);
  ASSERT_TRUE(fs::remove(dir.path() / "in.ome.zarr" / "0" / "1" / "0" / "2"));
  std::unique_ptr<SliceSource> source =
      omeZarrSliceSource(zarrFolderStore(dir.file("in.ome.zarr")), 0);
  ASSERT_NE(source, nullptr);
  writeOmeZarr(*source, dir.file("s.ome.zarr"), o);
  writeOmeZarr(loadVolume(dir.file("in.ome.zarr")), dir.file("w.ome.zarr"), o);
  std::string why;
  EXPECT_TRUE(sameFiles(dir.path() / "w.ome.zarr", dir.path() / "s.ome.zarr", why)) << why;
  const std::vector<std::string> w = source->warnings();
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("1 of 18 chunks are missing"), std::string::npos) << w[0];
}

}  // namespace
}  // namespace voxray::test
