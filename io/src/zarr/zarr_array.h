#pragma once
// One Zarr array (v2: .zarray; v3: zarr.json with node_type "array") as Voxray reads it: the
// shape, the regular chunk grid, the data type and byte order, the one compressor, the fill
// value and where each chunk's file is. Read from the array's metadata and checked before
// anything large is allocated.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../raw_samples.h"
#include "voxray/io/ome_zarr.h"
#include "zarr_codecs.h"

namespace voxray::zarr {

struct ArrayMeta {
  int format = 2;               // Zarr v2 or v3
  std::string path;             // the array's key prefix in the store ("0", "s1")
  std::string metadataFile;     // .zarray or zarr.json, where the store says it is, for messages
  std::vector<uint64_t> shape;  // C order: the last index varies fastest
  std::vector<uint64_t> chunks;
  detail::SampleKind kind = detail::SampleKind::I16;
  bool swap = false;          // the chunks' byte order is not this machine's
  std::string dataType;       // as the metadata names it ("<i2", "int16")
  Codec codec;                // the one compressor (or none)
  bool crc32cSuffix = false;  // v3 "crc32c": 4 checksum bytes after the compressed data
  double fill = 0.0;          // the value of a missing chunk (NaN for a float "NaN")
  std::string separator = ".";
  bool prefixC = false;  // v3's default key encoding: "c/0/1/2"

  size_t typeSize() const { return detail::sampleBytes(kind); }
  // Samples and bytes of one chunk (edge chunks are stored whole, too).
  uint64_t chunkSamples() const;
  // The chunk at grid position INDEX: its key below path.
  std::string chunkKey(const std::vector<uint64_t>& index) const;
  // Its key in the store.
  std::string storeKey(const std::string& chunk) const { return path + "/" + chunk; }
};

// Largest chunk Voxray decodes (uncompressed): beyond it the metadata is taken as damaged,
// before any buffer is allocated. 512 MiB is 4x a 256^3 float64 chunk; real writers use
// chunks of 1-64 MiB.
inline constexpr uint64_t kMaxChunkBytes = uint64_t(512) << 20;
// Most chunks in one array: a 2048^3 volume in 8^3 chunks. Beyond, a read would take hours.
inline constexpr uint64_t kMaxChunkCount = uint64_t(1) << 24;

// Reads and checks the array metadata of Zarr FORMAT (2 or 3) at PATH in STORE. Throws Error
// (Input) naming the metadata file and what is wrong.
ArrayMeta readArrayMeta(ZarrStore& store, const std::string& path, int format);
// The same from the metadata's bytes, named METADATA_FILE in messages (the fuzz target's
// entry: no store).
ArrayMeta parseArrayMeta(const std::vector<uint8_t>& bytes, const std::string& path,
                         const std::string& metadataFile, int format);

// Reads and parses the JSON file KEY. Throws Error (Input) naming it when it is missing, too
// large or not JSON.
nlohmann::json readJson(ZarrStore& store, const std::string& key);
// Parses BYTES as JSON. Throws Error (Input) naming WHERE when it is not JSON.
nlohmann::json parseJson(const std::vector<uint8_t>& bytes, const std::string& where);
// KEY's bytes, or false when STORE has no KEY; at most 16 MiB (metadata is small).
bool readMetadata(ZarrStore& store, const std::string& key, std::vector<uint8_t>& bytes);

}  // namespace voxray::zarr
