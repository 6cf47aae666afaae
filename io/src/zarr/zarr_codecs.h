#pragma once
// The chunk codecs of OME-Zarr, each through its packaged library: Blosc (libblosc, with its
// own lz4, zstd, zlib, blosclz inner codecs), zstd (libzstd), zlib and gzip (zlib). A chunk is
// decoded into a buffer of exactly the size its shape and data type give; anything else is a
// damaged chunk.
#include <cstdint>
#include <string>
#include <vector>

namespace voxray::zarr {

struct Codec {
  enum class Kind { None, Blosc, Zstd, Zlib, Gzip };
  Kind kind = Kind::None;
  std::string bloscInner = "zstd";  // Blosc's cname: blosclz, lz4, lz4hc, zlib, zstd
  int level = 5;
  int bloscShuffle = 1;  // 0 none, 1 byte shuffle, 2 bit shuffle
};

// Decodes DATA into OUT, whose size is the chunk's size in bytes. WHERE names the chunk (its
// file) in the message. Throws Error (Input) when the data is damaged, truncated or decodes
// to another size.
void decodeChunk(const Codec& codec, const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                 size_t typeSize, const std::string& where);

// Encodes RAW (one chunk, TYPE_SIZE bytes per sample). Throws Error (Output) on failure.
std::vector<uint8_t> encodeChunk(const Codec& codec, const std::vector<uint8_t>& raw,
                                 size_t typeSize);

}  // namespace voxray::zarr
