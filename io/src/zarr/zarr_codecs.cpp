#include "zarr_codecs.h"

#include <blosc.h>
#include <zlib.h>
#include <zstd.h>

#include <climits>

#include "voxray/io/error.h"

namespace voxray::zarr {
namespace {

[[noreturn]] void damaged(const std::string& where, const std::string& why) {
  throw inputError(where + ": the chunk is damaged or truncated (" + why +
                   "); write the array again, or delete the chunk to read it as empty");
}

void decodeBlosc(const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                 const std::string& where) {
  size_t nbytes = 0;
  // Checks the header against the buffer's length before anything is decompressed.
  if (data.size() < BLOSC_MIN_HEADER_LENGTH ||
      blosc_cbuffer_validate(data.data(), data.size(), &nbytes) != 0)
    damaged(where, "not a valid Blosc buffer of " + std::to_string(data.size()) + " bytes");
  if (nbytes != out.size())
    damaged(where, "Blosc holds " + std::to_string(nbytes) + " bytes, the chunk needs " +
                       std::to_string(out.size()));
  // One thread per call: chunks are decoded in parallel already.
  const int got = blosc_decompress_ctx(data.data(), out.data(), out.size(), 1);
  if (got < 0 || size_t(got) != out.size())
    damaged(where, "Blosc could not decompress it (code " + std::to_string(got) + ")");
}

void decodeZstd(const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                const std::string& where) {
  const unsigned long long content = ZSTD_getFrameContentSize(data.data(), data.size());
  if (content == ZSTD_CONTENTSIZE_ERROR) damaged(where, "not a zstd frame");
  if (content != ZSTD_CONTENTSIZE_UNKNOWN && content != out.size())
    damaged(where, "zstd holds " + std::to_string(content) + " bytes, the chunk needs " +
                       std::to_string(out.size()));
  const size_t got = ZSTD_decompress(out.data(), out.size(), data.data(), data.size());
  if (ZSTD_isError(got)) damaged(where, std::string("zstd: ") + ZSTD_getErrorName(got));
  if (got != out.size())
    damaged(where, "zstd gave " + std::to_string(got) + " bytes, the chunk needs " +
                       std::to_string(out.size()));
}

// zlib (Zarr v2's "zlib") and gzip alike: inflate detects which header it has.
void decodeInflate(const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                   const std::string& where) {
  if (data.size() > UINT_MAX || out.size() > UINT_MAX) damaged(where, "larger than 4 GiB");
  z_stream s{};
  if (inflateInit2(&s, 15 + 32) != Z_OK) throw outputError("zlib: cannot start inflate");
  s.next_in = const_cast<Bytef*>(data.data());
  s.avail_in = uInt(data.size());
  s.next_out = out.data();
  s.avail_out = uInt(out.size());
  const int rc = inflate(&s, Z_FINISH);
  const size_t got = s.total_out;
  inflateEnd(&s);
  if (rc != Z_STREAM_END)
    damaged(
        where,
        rc == Z_BUF_ERROR && got == out.size()
            ? "it decompresses to more than the chunk's " + std::to_string(out.size()) + " bytes"
            : "deflate stream ends early or is corrupt after " + std::to_string(got) + " bytes");
  if (got != out.size())
    damaged(where, "it decompresses to " + std::to_string(got) + " bytes, the chunk needs " +
                       std::to_string(out.size()));
}

std::vector<uint8_t> encodeDeflate(const std::vector<uint8_t>& raw, int level, bool gzip) {
  z_stream s{};
  if (deflateInit2(&s, level, Z_DEFLATED, gzip ? 15 + 16 : 15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw outputError("zlib: cannot start deflate");
  std::vector<uint8_t> out(deflateBound(&s, uLong(raw.size())) + 32);
  s.next_in = const_cast<Bytef*>(raw.data());
  s.avail_in = uInt(raw.size());
  s.next_out = out.data();
  s.avail_out = uInt(out.size());
  const int rc = deflate(&s, Z_FINISH);
  out.resize(s.total_out);
  deflateEnd(&s);
  if (rc != Z_STREAM_END)
    throw outputError("zlib: deflate failed (code " + std::to_string(rc) + ")");
  return out;
}

}  // namespace

void decodeChunk(const Codec& codec, const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                 size_t /*typeSize*/, const std::string& where) {
  switch (codec.kind) {
    case Codec::Kind::None:
      if (data.size() != out.size())
        damaged(where, "it has " + std::to_string(data.size()) + " bytes, the chunk needs " +
                           std::to_string(out.size()));
      out = data;
      return;
    case Codec::Kind::Blosc:
      return decodeBlosc(data, out, where);
    case Codec::Kind::Zstd:
      return decodeZstd(data, out, where);
    case Codec::Kind::Zlib:
    case Codec::Kind::Gzip:
      return decodeInflate(data, out, where);
  }
}

std::vector<uint8_t> encodeChunk(const Codec& codec, const std::vector<uint8_t>& raw,
                                 size_t typeSize) {
  switch (codec.kind) {
    case Codec::Kind::None:
      return raw;
    case Codec::Kind::Blosc: {
      std::vector<uint8_t> out(raw.size() + BLOSC_MAX_OVERHEAD);
      const int n =
          blosc_compress_ctx(codec.level, codec.bloscShuffle, typeSize, raw.size(), raw.data(),
                             out.data(), out.size(), codec.bloscInner.c_str(), 0, 1);
      if (n <= 0) throw outputError("Blosc (" + codec.bloscInner + ") could not compress a chunk");
      out.resize(size_t(n));
      return out;
    }
    case Codec::Kind::Zstd: {
      std::vector<uint8_t> out(ZSTD_compressBound(raw.size()));
      const size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), codec.level);
      if (ZSTD_isError(n)) throw outputError(std::string("zstd: ") + ZSTD_getErrorName(n));
      out.resize(n);
      return out;
    }
    case Codec::Kind::Zlib:
      return encodeDeflate(raw, codec.level, false);
    case Codec::Kind::Gzip:
      return encodeDeflate(raw, codec.level, true);
  }
  return raw;
}

}  // namespace voxray::zarr
