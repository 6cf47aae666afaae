#include "zarr_array.h"

#include <bit>
#include <cmath>
#include <limits>
#include <sstream>

#include "voxray/io/error.h"

namespace voxray::zarr {
namespace {

using detail::SampleKind;
using Json = nlohmann::json;

// Metadata files are small; a larger one is not metadata (or is hostile).
constexpr uint64_t kMaxJsonBytes = 16u << 20;

bool littleEndianMachine() { return std::endian::native == std::endian::little; }

[[noreturn]] void bad(const ArrayMeta& m, const std::string& what) {
  throw inputError(m.metadataFile + ": " + what);
}

const Json& member(const ArrayMeta& m, const Json& j, const char* key) {
  if (!j.is_object() || !j.contains(key)) bad(m, std::string("has no \"") + key + "\"");
  return j.at(key);
}

std::vector<uint64_t> dimsOf(const ArrayMeta& m, const Json& j, const char* what) {
  if (!j.is_array() || j.empty()) bad(m, std::string(what) + " is not a list of sizes");
  std::vector<uint64_t> out;
  for (const Json& d : j) {
    if (!d.is_number_integer() || d.get<int64_t>() < 1)
      bad(m, std::string(what) + " " + j.dump() + " is not a list of positive whole numbers");
    out.push_back(d.get<uint64_t>());
  }
  return out;
}

[[noreturn]] void unknownType(const ArrayMeta& m, const std::string& name) {
  bad(m, "the data type " + name +
             " is not one Voxray reads; it reads int8, uint8, int16, uint16, int32, uint32, "
             "float32 and float64 (convert the array to one of those)");
}

// v2: "<i2", ">u2", "|u1", "<f4" ...
void setV2Type(ArrayMeta& m, const Json& j) {
  if (!j.is_string()) unknownType(m, j.dump());
  const std::string t = j.get<std::string>();
  m.dataType = t;
  if (t.size() != 3 || (t[0] != '<' && t[0] != '>' && t[0] != '|')) unknownType(m, "'" + t + "'");
  static const std::pair<const char*, SampleKind> kinds[] = {
      {"i1", SampleKind::I8},  {"u1", SampleKind::U8},  {"i2", SampleKind::I16},
      {"u2", SampleKind::U16}, {"i4", SampleKind::I32}, {"u4", SampleKind::U32},
      {"f4", SampleKind::F32}, {"f8", SampleKind::F64}};
  for (const auto& [code, kind] : kinds)
    if (t.compare(1, 2, code) == 0) {
      m.kind = kind;
      m.swap = m.typeSize() > 1 && ((t[0] == '>') == littleEndianMachine());
      return;
    }
  unknownType(m, "'" + t + "'");
}

void setV3Type(ArrayMeta& m, const Json& j) {
  if (!j.is_string()) unknownType(m, j.dump());
  const std::string t = j.get<std::string>();
  m.dataType = t;
  static const std::pair<const char*, SampleKind> kinds[] = {
      {"int8", SampleKind::I8},     {"uint8", SampleKind::U8},   {"int16", SampleKind::I16},
      {"uint16", SampleKind::U16},  {"int32", SampleKind::I32},  {"uint32", SampleKind::U32},
      {"float32", SampleKind::F32}, {"float64", SampleKind::F64}};
  for (const auto& [name, kind] : kinds)
    if (t == name) {
      m.kind = kind;
      return;
    }
  unknownType(m, "'" + t + "'");
}

double fillOf(const ArrayMeta& m, const Json& j) {
  if (j.is_null()) return 0.0;
  if (j.is_boolean()) return j.get<bool>() ? 1.0 : 0.0;
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s == "NaN") return std::numeric_limits<double>::quiet_NaN();
    if (s == "Infinity") return std::numeric_limits<double>::infinity();
    if (s == "-Infinity") return -std::numeric_limits<double>::infinity();
  }
  bad(m, "fill_value " + j.dump() + " is not a number");
}

// A missing chunk's samples are the fill value in the array's type: it must be one of them
// (converting 1e308 to int16 is undefined). A non-finite fill of an integer type reads as 0.
void checkFill(const ArrayMeta& m) {
  if (!std::isfinite(m.fill)) return;
  double lo = -std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::max();
  switch (m.kind) {
    case SampleKind::U8:
      lo = 0, hi = 255;
      break;
    case SampleKind::I8:
      lo = -128, hi = 127;
      break;
    case SampleKind::U16:
      lo = 0, hi = 65535;
      break;
    case SampleKind::I16:
      lo = -32768, hi = 32767;
      break;
    case SampleKind::U32:
      lo = 0, hi = 4294967295.0;
      break;
    case SampleKind::I32:
      lo = -2147483648.0, hi = 2147483647.0;
      break;
    case SampleKind::F32:
      break;
    case SampleKind::F64:
      return;
  }
  if (m.fill < lo || m.fill > hi) {
    std::ostringstream text;
    text << "fill_value " << m.fill << " is not a value of " << m.dataType << " (" << lo << " to "
         << hi << "); the metadata is damaged: write the array again";
    bad(m, text.str());
  }
}

Codec bloscOf(const ArrayMeta& m, const Json& config) {
  Codec c;
  c.kind = Codec::Kind::Blosc;
  if (config.contains("cname") && config["cname"].is_string())
    c.bloscInner = config["cname"].get<std::string>();
  static const char* const known[] = {"blosclz", "lz4", "lz4hc", "zlib", "zstd", "snappy"};
  bool ok = false;
  for (const char* k : known) ok = ok || c.bloscInner == k;
  if (!ok) bad(m, "Blosc's inner codec '" + c.bloscInner + "' is not one Blosc knows");
  return c;
}

void setV2Compressor(ArrayMeta& m, const Json& j) {
  if (j.is_null()) return;
  if (!j.is_object() || !j.contains("id") || !j["id"].is_string())
    bad(m, "compressor " + j.dump() + " has no id");
  const std::string id = j["id"].get<std::string>();
  if (id == "blosc")
    m.codec = bloscOf(m, j);
  else if (id == "zstd")
    m.codec.kind = Codec::Kind::Zstd;
  else if (id == "zlib")
    m.codec.kind = Codec::Kind::Zlib;
  else if (id == "gzip")
    m.codec.kind = Codec::Kind::Gzip;
  else
    bad(m, "the compressor '" + id +
               "' is not one Voxray reads (blosc, zstd, zlib, gzip or none); write the array "
               "again with one of those");
}

void setV3Codecs(ArrayMeta& m, const Json& codecs) {
  if (!codecs.is_array() || codecs.empty()) bad(m, "\"codecs\" is not a list of codecs");
  bool haveBytes = false, haveCompressor = false;
  for (const Json& c : codecs) {
    const std::string name = c.is_object() && c.contains("name") && c["name"].is_string()
                                 ? c["name"].get<std::string>()
                                 : std::string();
    const Json config =
        c.is_object() && c.contains("configuration") ? c["configuration"] : Json::object();
    if (name == "bytes") {
      haveBytes = true;
      const std::string endian = config.contains("endian") && config["endian"].is_string()
                                     ? config["endian"].get<std::string>()
                                     : "little";
      if (endian != "little" && endian != "big") bad(m, "bytes codec endian '" + endian + "'");
      m.swap = m.typeSize() > 1 && ((endian == "big") == littleEndianMachine());
    } else if (name == "transpose") {
      const Json& order = config.contains("order") ? config["order"] : Json();
      bool identity = order.is_array();
      for (size_t i = 0; identity && i < order.size(); ++i)
        identity = order[i].is_number_integer() && order[i].get<int64_t>() == int64_t(i);
      if (!identity)
        bad(m, "the chunks are transposed (codec transpose " + order.dump() +
                   "); Voxray reads C-order chunks: write the array without transpose");
    } else if (name == "sharding_indexed") {
      bad(m,
          "the array is sharded (codec sharding_indexed), which Voxray does not read; write "
          "it without shards (voxray-cli convert writes plain chunks)");
    } else if (name == "crc32c") {
      m.crc32cSuffix = true;
    } else if (name == "blosc" || name == "zstd" || name == "gzip") {
      if (haveCompressor) bad(m, "has more than one compressor; Voxray reads one");
      haveCompressor = true;
      if (name == "blosc")
        m.codec = bloscOf(m, config);
      else
        m.codec.kind = name == "zstd" ? Codec::Kind::Zstd : Codec::Kind::Gzip;
    } else {
      bad(m, "the codec '" + (name.empty() ? c.dump() : name) +
                 "' is not one Voxray reads (bytes, blosc, zstd, gzip, crc32c)");
    }
  }
  if (!haveBytes) bad(m, "has no bytes codec (the array is not of numbers)");
}

void readV2(ArrayMeta& m, const Json& j) {
  if (member(m, j, "zarr_format") != 2) bad(m, "zarr_format is not 2");
  m.shape = dimsOf(m, member(m, j, "shape"), "shape");
  m.chunks = dimsOf(m, member(m, j, "chunks"), "chunks");
  setV2Type(m, member(m, j, "dtype"));
  setV2Compressor(m, member(m, j, "compressor"));
  if (j.contains("order") && j["order"] != "C")
    bad(m,
        "the chunks are in Fortran order (\"order\": \"F\"); Voxray reads C order: write "
        "the array again with order C");
  if (j.contains("filters") && !j["filters"].is_null() && !j["filters"].empty())
    bad(m, "has filters " + j["filters"].dump() +
               ", which Voxray does not apply; write the "
               "array again without filters");
  m.fill = fillOf(m, j.value("fill_value", Json()));
  m.separator = ".";
  if (j.contains("dimension_separator")) {
    const Json& s = j["dimension_separator"];
    if (s != "." && s != "/") bad(m, "dimension_separator " + s.dump() + " is neither . nor /");
    m.separator = s.get<std::string>();
  }
}

void readV3(ArrayMeta& m, const Json& j) {
  if (member(m, j, "zarr_format") != 3) bad(m, "zarr_format is not 3");
  if (member(m, j, "node_type") != "array") bad(m, "is not an array (node_type is not array)");
  m.shape = dimsOf(m, member(m, j, "shape"), "shape");
  const Json& grid = member(m, j, "chunk_grid");
  if (!grid.is_object() || grid.value("name", "") != "regular")
    bad(m, "chunk_grid " + grid.dump() + " is not regular; Voxray reads regular chunk grids");
  m.chunks = dimsOf(m, member(m, member(m, grid, "configuration"), "chunk_shape"), "chunk_shape");
  setV3Type(m, member(m, j, "data_type"));
  setV3Codecs(m, member(m, j, "codecs"));
  m.fill = fillOf(m, j.value("fill_value", Json()));
  if (j.contains("storage_transformers") && !j["storage_transformers"].empty())
    bad(m, "has storage transformers, which Voxray does not apply");
  m.prefixC = true;
  m.separator = "/";
  if (j.contains("chunk_key_encoding")) {
    const Json& e = j["chunk_key_encoding"];
    const std::string name = e.is_object() ? e.value("name", "") : "";
    if (name != "default" && name != "v2")
      bad(m, "chunk_key_encoding " + e.dump() + " is neither default nor v2");
    m.prefixC = name == "default";
    m.separator = m.prefixC ? "/" : ".";
    if (e.contains("configuration") && e["configuration"].contains("separator")) {
      const Json& s = e["configuration"]["separator"];
      if (s != "." && s != "/")
        bad(m, "the chunk key separator " + s.dump() + " is neither . nor /");
      m.separator = s.get<std::string>();
    }
  }
}

}  // namespace

bool readMetadata(ZarrStore& store, const std::string& key, std::vector<uint8_t>& bytes) {
  return store.read(key, bytes, kMaxJsonBytes, "is larger than 16 MiB; it is not Zarr metadata");
}

Json parseJson(const std::vector<uint8_t>& bytes, const std::string& where) {
  Json j = Json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (j.is_discarded())
    throw inputError(where + ": is not valid JSON; the Zarr metadata is damaged");
  return j;
}

Json readJson(ZarrStore& store, const std::string& key) {
  std::vector<uint8_t> bytes;
  if (!readMetadata(store, key, bytes))
    throw inputError(store.where(key) +
                     ": is missing; the Zarr folder is incomplete (copy it again)");
  return parseJson(bytes, store.where(key));
}

uint64_t ArrayMeta::chunkSamples() const {
  uint64_t n = 1;
  for (uint64_t c : chunks) n *= c;
  return n;
}

std::string ArrayMeta::chunkKey(const std::vector<uint64_t>& index) const {
  std::string key = prefixC ? "c" : "";
  for (size_t i = 0; i < index.size(); ++i) {
    if (!key.empty()) key += separator;
    key += std::to_string(index[i]);
  }
  return key;
}

ArrayMeta readArrayMeta(ZarrStore& store, const std::string& path, int format) {
  const std::string key = path + (format == 2 ? "/.zarray" : "/zarr.json");
  std::vector<uint8_t> bytes;
  if (!readMetadata(store, key, bytes))
    throw inputError(store.where(key) +
                     ": is missing; the Zarr folder is incomplete (copy it again)");
  return parseArrayMeta(bytes, path, store.where(key), format);
}

ArrayMeta parseArrayMeta(const std::vector<uint8_t>& document, const std::string& path,
                         const std::string& metadataFile, int format) {
  ArrayMeta m;
  m.format = format;
  m.path = path;
  m.metadataFile = metadataFile;
  const Json j = parseJson(document, metadataFile);
  if (!j.is_object()) bad(m, "is not a JSON object");
  try {
    if (format == 2)
      readV2(m, j);
    else
      readV3(m, j);
  } catch (const Json::exception& e) {
    bad(m, std::string("has a field of the wrong kind (") + e.what() + ")");
  }
  checkFill(m);
  if (m.chunks.size() != m.shape.size())
    bad(m, "the chunks have " + std::to_string(m.chunks.size()) + " dimensions, the shape " +
               std::to_string(m.shape.size()));
  // Before any chunk buffer exists: its size, and how many there are.
  uint64_t bytes = m.typeSize(), count = 1;
  for (size_t d = 0; d < m.shape.size(); ++d) {
    if (m.chunks[d] > kMaxChunkBytes || bytes > kMaxChunkBytes / m.chunks[d])
      bad(m, "a chunk would hold more than 512 MiB (chunks " + Json(m.chunks).dump() + " of " +
                 m.dataType +
                 "); the metadata is damaged, or write the array again "
                 "with smaller chunks");
    bytes *= m.chunks[d];
    const uint64_t along = (m.shape[d] + m.chunks[d] - 1) / m.chunks[d];
    if (along > kMaxChunkCount || count > kMaxChunkCount / along)
      bad(m, "the array has more than " + std::to_string(kMaxChunkCount) +
                 " chunks; write it again with larger chunks");
    count *= along;
  }
  return m;
}

}  // namespace voxray::zarr
