// The independent reader and writer: zarr-python (the venv's pinned zarr 3.1, through
// zarr_check.py) reads the pyramids Voxray writes, values and multiscales metadata; and
// Voxray reads OME-Zarr images that zarr-python writes (other data types, byte orders,
// codecs, key separators and units than Voxray's own).
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "voxray/io/load.h"
#include "zarr_test_support.h"

namespace fs = std::filesystem;

namespace voxray::test {
namespace {

// Runs zarr_check.py with ARGS; its output (one "OK ..." line, or what differs) in OUTPUT.
bool runCheck(const std::string& args, std::string& output) {
  if (!fs::exists(VOXRAY_PYTHON)) {
    output = "no Python with zarr at " VOXRAY_PYTHON ": run scripts/bootstrap";
    return false;
  }
  TempDir scratch;
  const std::string log = scratch.file("out.txt");
  const std::string command =
      "'" VOXRAY_PYTHON "' '" VOXRAY_ZARR_CHECK "' " + args + " > '" + log + "' 2>&1";
  const int rc = std::system(command.c_str());
  std::ifstream in(log);
  output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return rc == 0;
}

class ZarrPythonReads : public ::testing::TestWithParam<int> {};

TEST_P(ZarrPythonReads, VoxraysPyramidValuesAndMultiscalesMetadata) {
  const int version = GetParam();
  TempDir dir;
  const Volume v = zarrTestVolume();
  const std::string path = dir.file("v.ome.zarr");
  ZarrWriteOptions o;
  o.zarrVersion = version;
  o.chunk = 16;
  o.levels = 3;
  const ZarrWriteResult r = writeOmeZarr(v, path, o);
  // The truth for level 0, and what the metadata must say: scale and translation in the
  // volume's own axes, z, y, x (translation = direction^T * origin, + half a step per level).
  writeBytes(
      dir.file("level0.i16"),
      std::vector<uint8_t>(reinterpret_cast<const uint8_t*>(v.voxels.data()),
                           reinterpret_cast<const uint8_t*>(v.voxels.data()) + v.byteSize()));
  const glm::dvec3 t0 = glm::transpose(v.direction) * v.originMm;
  nlohmann::json levels = nlohmann::json::array();
  for (size_t l = 0; l < r.dims.size(); ++l) {
    const double f = double(1 << l);
    const glm::dvec3 s = v.spacingMm * f, t = t0 + v.spacingMm * ((f - 1) / 2);
    levels.push_back({{"shape", {r.dims[l].z, r.dims[l].y, r.dims[l].x}},
                      {"scale", {s.z, s.y, s.x}},
                      {"translation", {t.z, t.y, t.x}}});
  }
  std::ofstream(dir.file("expect.json")) << nlohmann::json{
      {"zarr_format", version},
      {"ngff", version == 2 ? "0.4" : "0.5"},
      {"dtype", "int16"},
      {"raw", dir.file("level0.i16")},
      {"levels", levels}}.dump();
  std::string output;
  EXPECT_TRUE(runCheck("read '" + path + "' '" + dir.file("expect.json") + "'", output)) << output;
  EXPECT_THAT(output, ::testing::HasSubstr("OK zarr 3.1.5 read 3 levels"));
}

INSTANTIATE_TEST_SUITE_P(ZarrV2AndV3, ZarrPythonReads, ::testing::Values(2, 3),
                         [](const ::testing::TestParamInfo<int>& i) {
                           return "V" + std::to_string(i.param);
                         });

class VoxrayReadsZarrPython : public ::testing::TestWithParam<std::string> {};

TEST_P(VoxrayReadsZarrPython, ValuesAndGeometryInMillimetres) {
  TempDir dir;
  const std::string path = dir.file("p.ome.zarr");
  std::string output;
  ASSERT_TRUE(runCheck("make '" + path + "' " + GetParam(), output)) << output;
  const auto expect = nlohmann::json::parse(std::ifstream(path + ".expected.json"));
  const std::vector<uint8_t> bytes = readBytes(path + ".expected.f64");
  std::vector<double> truth(bytes.size() / sizeof(double));
  std::memcpy(truth.data(), bytes.data(), truth.size() * sizeof(double));

  const Volume v = loadVolume(path);
  ASSERT_EQ(v.dims, glm::ivec3(expect["dims"][0], expect["dims"][1], expect["dims"][2]));
  ASSERT_EQ(truth.size(), v.voxelCount());
  size_t wrong = 0;
  for (size_t i = 0; i < truth.size(); ++i) wrong += v.toPhysical(v.voxels[i]) != truth[i];
  EXPECT_EQ(wrong, 0u) << "voxels whose value differs (the values are exact in int16 steps)";
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(v.spacingMm[a], expect["spacing_mm"][a].get<double>(), 1e-9) << a;
    EXPECT_NEAR(v.originMm[a], expect["origin_mm"][a].get<double>(), 1e-9) << a;
  }
  EXPECT_EQ(v.direction, glm::dmat3(1.0));  // NGFF has no orientation: i, j, k along L, P, S
  EXPECT_EQ(v.unit, "scanner units");       // nothing says HU
}

INSTANTIATE_TEST_SUITE_P(Variants, VoxrayReadsZarrPython,
                         ::testing::Values("v2-u16be-blosc-lz4-dot", "v3-f32-zstd",
                                           "v2-i16-gzip-slash", "v3-i16be-blosc"),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string name;
                           for (char c : i.param) name += std::isalnum((unsigned char)c) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace voxray::test
