// Bad OME-Zarr input: each gets a voxray::Error (Input) naming the file or chunk and saying
// what is wrong, before anything large is allocated; never a crash.
#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "voxray/io/load.h"
#include "zarr_test_support.h"

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using Json = nlohmann::json;

namespace voxray::test {
namespace {

class OmeZarrBadInput : public ::testing::Test {
 protected:
  // A valid one-level pyramid of the test volume in chunks of 16 (3 x 3 x 2 of them).
  std::string write(int version, ZarrCodec codec = ZarrCodec::BloscZstd) {
    ZarrWriteOptions o;
    o.zarrVersion = version;
    o.codec = codec;
    o.chunk = 16;
    o.levels = 1;
    writeOmeZarr(zarrTestVolume(), path_, o);
    return path_;
  }
  // Edits a JSON file of the pyramid in place.
  void edit(const std::string& relative, const std::function<void(Json&)>& change) {
    const std::string file = path_ + "/" + relative;
    Json j = Json::parse(std::ifstream(file));
    change(j);
    std::ofstream(file, std::ios::trunc) << j.dump();
  }
  std::string loadError(const LoadOptions& o = {}) {
    return errorMessage([&] { loadVolume(path_, o); });
  }
  std::string chunk(int version) const {
    return path_ + (version == 2 ? "/0/0/0/0" : "/0/c/0/0/0");
  }
  void truncate(const std::string& file) {
    std::vector<uint8_t> bytes = readBytes(file);
    bytes.resize(bytes.size() / 2);
    writeBytes(file, bytes);
  }

  TempDir dir_;
  std::string path_ = dir_.file("bad.ome.zarr");
};

TEST_F(OmeZarrBadInput, AnUnknownDataTypeIsNamed) {
  write(2);
  edit("0/.zarray", [](Json& j) { j["dtype"] = "<c8"; });
  EXPECT_THAT(loadError(), HasSubstr("0/.zarray: the data type '<c8' is not one Voxray reads"));
}

TEST_F(OmeZarrBadInput, AnUnknownV3DataTypeIsNamed) {
  write(3);
  edit("0/zarr.json", [](Json& j) { j["data_type"] = "complex64"; });
  EXPECT_THAT(loadError(), HasSubstr("0/zarr.json: the data type 'complex64' is not one Voxray "
                                     "reads; it reads int8, uint8, int16, uint16"));
}

TEST_F(OmeZarrBadInput, AShapeThatDisagreesWithTheAxesIsRefused) {
  write(2);
  edit("0/.zarray", [](Json& j) {
    j["shape"] = {38, 45};
    j["chunks"] = {16, 16};
  });
  EXPECT_THAT(loadError(), HasSubstr("0/.zarray: the array has 2 dimensions but the multiscales "
                                     "metadata names 3 axes"));
}

TEST_F(OmeZarrBadInput, ChunksOfAnotherRankThanTheShapeAreRefused) {
  write(3);
  edit("0/zarr.json", [](Json& j) { j["chunk_grid"]["configuration"]["chunk_shape"] = {16, 16}; });
  EXPECT_THAT(loadError(), HasSubstr("0/zarr.json: the chunks have 2 dimensions, the shape 3"));
}

TEST_F(OmeZarrBadInput, AbsurdChunkSizesAreRefusedBeforeAnyAllocation) {
  write(2);
  edit("0/.zarray", [](Json& j) { j["chunks"] = {100000, 100000, 100000}; });
  EXPECT_THAT(loadError(), HasSubstr("0/.zarray: a chunk would hold more than 512 MiB (chunks "
                                     "[100000,100000,100000] of <i2)"));
  edit("0/.zarray", [](Json& j) {
    j["shape"] = {2048, 2048, 2048};
    j["chunks"] = {1, 1, 1};
  });
  EXPECT_THAT(loadError(), HasSubstr("the array has more than 16777216 chunks"));
  edit("0/.zarray", [](Json& j) { j["chunks"] = {0, 16, 16}; });
  EXPECT_THAT(loadError(), HasSubstr("chunks [0,16,16] is not a list of positive whole numbers"));
}

TEST_F(OmeZarrBadInput, AShapeBeyondWhatVoxrayHoldsIsRefusedBeforeReading) {
  write(2);
  edit("0/.zarray", [](Json& j) {
    j["shape"] = {4096, 4096, 4096};
    j["chunks"] = {512, 512, 512};
  });
  EXPECT_THAT(loadError(), HasSubstr("has more voxels than Voxray can hold"));
}

TEST_F(OmeZarrBadInput, ATruncatedChunkIsNamedForEveryCodec) {
  for (int version : {2, 3})
    for (ZarrCodec codec :
         {ZarrCodec::BloscZstd, ZarrCodec::Zstd, ZarrCodec::Gzip, ZarrCodec::None}) {
      fs::remove_all(path_);
      write(version, codec);
      truncate(chunk(version));
      const std::string message = loadError();
      EXPECT_THAT(message, HasSubstr(chunk(version) + ": the chunk is damaged or truncated ("))
          << version << " " << int(codec);
      EXPECT_THAT(message, HasSubstr("write the array again, or delete the chunk to read it as "
                                     "empty"));
    }
}

TEST_F(OmeZarrBadInput, GarbageChunksAreRefusedForEveryCodecAndNeverCrash) {
  // Headers that claim more than they hold: Blosc (version 2, nbytes 8192, cbytes 1 GiB), a
  // zstd frame of another content size, gzip's magic then noise; empty and random files.
  const std::vector<std::vector<uint8_t>> blobs = {
      {},
      {2, 1, 0x21, 2, 0x00, 0x20, 0, 0, 0x00, 0x20, 0, 0, 0, 0, 0, 0x40},
      {0x28, 0xb5, 0x2f, 0xfd, 0x20, 0x10, 0x01, 0x00, 0x00, 0x41},
      {0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 3, 0xde, 0xad, 0xbe, 0xef},
      std::vector<uint8_t>(100, 0xa5)};
  for (ZarrCodec codec :
       {ZarrCodec::BloscZstd, ZarrCodec::Zstd, ZarrCodec::Gzip, ZarrCodec::None}) {
    fs::remove_all(path_);
    write(2, codec);
    for (const auto& blob : blobs) {
      writeBytes(chunk(2), blob);
      EXPECT_THAT(loadError(), HasSubstr(chunk(2) + ": the chunk is damaged or truncated ("))
          << int(codec) << ", " << blob.size() << " bytes";
    }
  }
}

TEST_F(OmeZarrBadInput, AnUncompressedChunkOfTheWrongSizeSaysBoth) {
  write(2, ZarrCodec::None);
  truncate(chunk(2));
  EXPECT_THAT(loadError(), HasSubstr("(it has 4096 bytes, the chunk needs 8192)"));
}

TEST_F(OmeZarrBadInput, MetadataThatIsNotJsonIsNamed) {
  write(3);
  std::ofstream(path_ + "/zarr.json", std::ios::trunc) << "{\"zarr_format\": 3,";
  EXPECT_THAT(loadError(), HasSubstr("zarr.json: is not valid JSON; the Zarr metadata is damaged"));
}

TEST_F(OmeZarrBadInput, AFolderWithoutZarrMetadataSaysWhatItLacks) {
  fs::create_directories(path_);
  EXPECT_THAT(loadError(), HasSubstr("holds neither zarr.json (Zarr v3) nor .zattrs (Zarr v2): it "
                                     "is not an OME-Zarr folder"));
}

TEST_F(OmeZarrBadInput, APlainZarrGroupIsNotAnImage) {
  write(2);
  edit(".zattrs", [](Json& j) { j.erase("multiscales"); });
  EXPECT_THAT(loadError(), HasSubstr("has no OME-NGFF multiscales metadata"));
}

TEST_F(OmeZarrBadInput, ShardedArraysAreRefusedWithWhatToDo) {
  write(3);
  edit("0/zarr.json", [](Json& j) {
    j["codecs"] = Json::array({{{"name", "sharding_indexed"}, {"configuration", Json::object()}}});
  });
  EXPECT_THAT(loadError(), HasSubstr("the array is sharded (codec sharding_indexed)"));
}

TEST_F(OmeZarrBadInput, FortranOrderIsRefused) {
  write(2);
  edit("0/.zarray", [](Json& j) { j["order"] = "F"; });
  EXPECT_THAT(loadError(), HasSubstr("the chunks are in Fortran order"));
}

TEST_F(OmeZarrBadInput, AnAxisUnitThatIsNoLengthAndANonPositiveScaleAreRefused) {
  write(2);
  edit(".zattrs", [](Json& j) { j["multiscales"][0]["axes"][1]["unit"] = "second"; });
  EXPECT_THAT(loadError(), HasSubstr("the axis 'y' has the unit 'second', not a length"));
  edit(".zattrs", [](Json& j) {
    j["multiscales"][0]["axes"][1]["unit"] = "micrometer";
    j["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"][2] = 0.0;
  });
  EXPECT_THAT(loadError(), HasSubstr("has the scale 0.000000 along 'x'; a voxel size must be "
                                     "positive"));
}

TEST_F(OmeZarrBadInput, ALevelBeyondThePyramidIsRefused) {
  write(3);
  LoadOptions o;
  o.level = 1;
  EXPECT_THAT(loadError(o),
              HasSubstr("--level 1 is out of range: the pyramid has 1 level (0 to 0)"));
}

TEST_F(OmeZarrBadInput, AZarrV2GroupWithoutAttributesIsNotAnImage) {
  write(2);
  fs::remove(path_ + "/.zattrs");
  EXPECT_THAT(loadError(), HasSubstr("has no OME-NGFF multiscales metadata"));
}

TEST_F(OmeZarrBadInput, ALevelForAnInputOfOneResolutionIsRefused) {
  writeBytes(dir_.file("plain.raw"), std::vector<uint8_t>(16, 0));
  LoadOptions o;
  o.level = 2;
  EXPECT_THAT(errorMessage([&] { loadVolume(dir_.file("plain.raw"), o); }),
              HasSubstr("--level 2 picks a level of an OME-Zarr pyramid; this input has one "
                        "resolution"));
}

TEST_F(OmeZarrBadInput, ADatasetPathLeavingTheFolderIsRefused) {
  write(2);
  edit(".zattrs", [](Json& j) { j["multiscales"][0]["datasets"][0]["path"] = "../../etc"; });
  EXPECT_THAT(loadError(), HasSubstr("the dataset path '../../etc' leaves the folder"));
}

// Found with voxray_zarr_metadata_fuzzer's inputs (tests/fuzz): each used to reach undefined
// behaviour or a wrong volume before it was refused.

// A fill value outside the data type: converting 1e308 to int16 for a missing chunk was
// undefined (UBSan: "outside the range of representable values of type 'short'").
TEST_F(OmeZarrBadInput, AFillValueOutsideTheDataTypeIsRefused) {
  write(2);
  edit("0/.zarray", [](Json& j) { j["fill_value"] = 1e308; });
  EXPECT_THAT(loadError(), HasSubstr("0/.zarray: fill_value 1e+308 is not a value of <i2 (-32768 "
                                     "to 32767); the metadata is damaged"));
  fs::remove_all(path_);
  write(3);
  edit("0/zarr.json", [](Json& j) { j["fill_value"] = -1; });
  edit("0/zarr.json", [](Json& j) { j["data_type"] = "uint8"; });
  EXPECT_THAT(loadError(), HasSubstr("0/zarr.json: fill_value -1 is not a value of uint8 (0 to "
                                     "255)"));
}

// 2^33 voxels along x (and 1 along y and z) is within kMaxVoxels, but an axis of a Volume is
// an int: it became 0 voxels wide.
TEST_F(OmeZarrBadInput, AnAxisLongerThanAVolumeHoldsIsRefused) {
  write(2);
  edit("0/.zarray", [](Json& j) {
    j["shape"] = {1, 1, uint64_t(1) << 33};
    j["chunks"] = {1, 1, 65536};
  });
  EXPECT_THAT(loadError(), HasSubstr("0/.zarray: the shape [1,1,8589934592] has 8589934592 "
                                     "voxels along x; Voxray holds at most 2147483647 along an "
                                     "axis"));
}

// Finite numbers whose product is not: a global scale of 1e300 times a translation of 1e300
// gave an infinite origin; a scale of 1e308 mm times 45 voxels an infinite extent.
TEST_F(OmeZarrBadInput, ATranslationOrExtentBeyondAnyLengthIsRefused) {
  write(2);
  edit(".zattrs", [](Json& j) {
    auto& ms = j["multiscales"][0];
    ms["coordinateTransformations"] =
        Json::parse(R"([{"type": "scale", "scale": [1e300, 1e300, 1e300]}])");
    ms["datasets"][0]["coordinateTransformations"] = Json::parse(
        R"([{"type": "scale", "scale": [1e-300, 1e-300, 1e-300]},
            {"type": "translation", "translation": [0, 0, 1e300]}])");
  });
  EXPECT_THAT(loadError(), HasSubstr("the dataset '0' has a translation along 'x' beyond any "
                                     "length"));
  fs::remove_all(path_);
  write(2);
  edit(".zattrs", [](Json& j) {
    j["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"][2] = 1e308;
  });
  EXPECT_THAT(loadError(), HasSubstr("0/.zarray: level 0 reaches beyond any length (its origin "
                                     "or extent along x passes 1e308 mm)"));
}

}  // namespace
}  // namespace voxray::test
