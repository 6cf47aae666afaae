#include "nifti_header_check.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>

namespace voxray::formats {
namespace {

constexpr size_t kNifti1Bytes = 348, kNifti2Bytes = 540;

// Reads a little- or big-endian integer of N bytes at OFFSET.
int64_t field(const uint8_t* h, size_t offset, size_t n, bool swap) {
  uint64_t v = 0;
  for (size_t i = 0; i < n; ++i) v |= uint64_t(h[offset + (swap ? n - 1 - i : i)]) << (8 * i);
  if (n < 8 && (v >> (8 * n - 1)) & 1) v |= ~uint64_t(0) << (8 * n);  // sign-extend
  return int64_t(v);
}

bool knownDatatype(int64_t t) {  // NIfTI's DT_* codes (nifti1.h)
  static constexpr std::array<int64_t, 16> kCodes = {2,   4,   8,    16,   32,   64,   128,  256,
                                                     512, 768, 1024, 1280, 1536, 1792, 2048, 2304};
  return std::find(kCodes.begin(), kCodes.end(), t) != kCodes.end();
}

}  // namespace

std::string niftiHeaderProblem(const std::string& path) {
  std::unique_ptr<gzFile_s, int (*)(gzFile)> f(gzopen(path.c_str(), "rb"), &gzclose);
  if (!f) return "it cannot be opened";
  uint8_t h[kNifti2Bytes] = {};
  const int got = gzread(f.get(), h, sizeof h);
  if (got < int(kNifti1Bytes)) return "the header is shorter than 348 bytes";
  bool swap = false;
  size_t bytes = 0;
  for (bool s : {false, true})
    for (size_t n : {kNifti1Bytes, kNifti2Bytes})
      if (field(h, 0, 4, s) == int64_t(n)) {
        swap = s;
        bytes = n;
      }
  if (bytes == 0) return "sizeof_hdr is neither 348 (NIfTI-1) nor 540 (NIfTI-2)";
  if (got < int(bytes)) return "the NIfTI-2 header is shorter than 540 bytes";
  const bool two = bytes == kNifti2Bytes;
  const uint8_t* magic = two ? h + 4 : h + 344;
  if (std::memcmp(magic + 1, two ? "i2" : "i1", 2) != 0 &&
      std::memcmp(magic + 1, two ? "+2" : "+1", 2) != 0)
    return "the magic is neither n+1/ni1 nor n+2/ni2";
  if (magic[0] != 'n' || magic[3] != 0) return "the magic is damaged";
  const size_t dimAt = two ? 16 : 40, dimBytes = two ? 8 : 2;
  const int64_t rank = field(h, dimAt, dimBytes, swap);
  if (rank < 1 || rank > 7) return "dim[0] is " + std::to_string(rank) + ", not 1 ... 7";
  for (int64_t a = 1; a <= rank; ++a)
    if (field(h, dimAt + size_t(a) * dimBytes, dimBytes, swap) < 1)
      return "dim[" + std::to_string(a) + "] is below 1";
  const int64_t type = field(h, two ? 12 : 70, 2, swap);
  if (!knownDatatype(type)) return "the datatype " + std::to_string(type) + " is not a NIfTI one";
  return "";
}

}  // namespace voxray::formats
