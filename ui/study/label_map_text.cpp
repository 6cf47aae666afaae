#include "label_map_text.h"

#include <array>

#include <zlib.h>

#include "voxray/io/error.h"

namespace voxray {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(const std::vector<uint8_t>& in) {
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (size_t i = 0; i < in.size(); i += 3) {
    const uint32_t n = uint32_t(in[i]) << 16 | (i + 1 < in.size() ? uint32_t(in[i + 1]) << 8 : 0) |
                       (i + 2 < in.size() ? uint32_t(in[i + 2]) : 0);
    out += kAlphabet[n >> 18 & 63];
    out += kAlphabet[n >> 12 & 63];
    out += i + 1 < in.size() ? kAlphabet[n >> 6 & 63] : '=';
    out += i + 2 < in.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

bool unbase64(const std::string& in, std::vector<uint8_t>& out) {
  std::array<int, 256> value;
  value.fill(-1);
  for (int i = 0; i < 64; ++i) value[size_t((unsigned char)kAlphabet[i])] = i;
  if (in.size() % 4) return false;
  out.clear();
  out.reserve(in.size() / 4 * 3);
  for (size_t i = 0; i < in.size(); i += 4) {
    int v[4];
    int pad = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = in[i + size_t(k)];
      if (c == '=' && i + 4 == in.size() && k >= 2) {
        v[k] = 0;
        ++pad;
        continue;
      }
      if (pad) return false;  // a character after padding
      v[k] = value[size_t((unsigned char)c)];
      if (v[k] < 0) return false;
    }
    const uint32_t n =
        uint32_t(v[0]) << 18 | uint32_t(v[1]) << 12 | uint32_t(v[2]) << 6 | uint32_t(v[3]);
    out.push_back(uint8_t(n >> 16));
    if (pad < 2) out.push_back(uint8_t(n >> 8));
    if (pad < 1) out.push_back(uint8_t(n));
  }
  return true;
}

}  // namespace

std::string labelMapToText(const std::vector<uint8_t>& labels) {
  uLongf size = compressBound(uLong(labels.size()));
  std::vector<uint8_t> packed(size);
  if (compress2(packed.data(), &size, labels.data(), uLong(labels.size()), 6) != Z_OK)
    throw Error(Error::Kind::Internal, "zlib could not compress the label map");
  packed.resize(size);
  return base64(packed);
}

std::vector<uint8_t> labelMapFromText(const std::string& text, size_t voxels,
                                      const std::string& field) {
  std::vector<uint8_t> packed;
  if (!unbase64(text, packed))
    throw inputError(field + " is not base64 text: the session was damaged or edited by hand.");
  // One byte more than expected tells a longer map (Z_BUF_ERROR) from an exact one.
  std::vector<uint8_t> labels(voxels + 1);
  uLongf size = uLongf(labels.size());
  const int rc = uncompress(labels.data(), &size, packed.data(), uLong(packed.size()));
  if (rc != Z_OK || size != voxels)
    throw inputError(field + " does not hold " + std::to_string(voxels) +
                     " labels (one per voxel of its grid): the session was damaged or edited "
                     "by hand.");
  labels.resize(voxels);
  return labels;
}

}  // namespace voxray
