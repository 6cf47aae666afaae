#pragma once
// Decoding raw samples and fitting their rescaled values into the 16-bit voxels of a
// Volume (physical = stored * slope + intercept).
#include <cstddef>
#include <cstdint>
#include <string>

#include "voxray/io/raw_import.h"

namespace voxray::detail {

// How to read one sample: its type, byte order and rescale. Raw layouts give one; so do the
// NIfTI/NRRD/MetaImage readers, which know more sample types than raw input offers.
enum class SampleKind { U8, I8, U16, I16, U32, I32, F32, F64 };
struct SampleDecoding {
  SampleKind kind = SampleKind::I16;
  bool swap = false;  // bytes are in the other order than this machine's
  double slope = 1.0, intercept = 0.0;
};
SampleKind kindOf(SampleType type);
SampleDecoding decodingOf(const RawLayout& layout);
size_t sampleBytes(SampleKind kind);
bool isIntegerKind(SampleKind kind);

// Range of hu = raw * slope + intercept over some samples; non-finite values are counted,
// not ranged.
struct ValueStats {
  double min = 0, max = 0;
  bool any = false;      // at least one finite value
  bool integral = true;  // every finite value is a whole number
  size_t nonFinite = 0;
  void merge(const ValueStats& other);
};
ValueStats scanSamples(const uint8_t* raw, size_t count, const SampleDecoding& decoding);

struct Storage {
  double slope = 1.0, intercept = 0.0;
  double fill = 0.0;    // physical value given to NaN and infinite samples
  std::string warning;  // empty unless the user should know how the values were stored
};
// Chooses the storage for values described by `stats`, read as `decoding`.
Storage chooseStorage(const ValueStats& stats, const SampleDecoding& decoding);

// The voxel storeSamples gives the finite physical value VALUE under STORAGE. Rounding and
// clamping never decrease as VALUE grows (STORAGE's slope is positive), so the stored values'
// range is that of the smallest and the largest value.
int16_t storedValue(double value, const Storage& storage);

// Decodes samples to doubles: raw * slope + intercept of DECODING.
void decodeSamples(const uint8_t* raw, size_t count, const SampleDecoding& decoding, double* out);

// Converts samples to stored voxels: round((hu - intercept) / slope).
void storeSamples(const uint8_t* raw, size_t count, const SampleDecoding& decoding,
                  const Storage& storage, int16_t* out);

}  // namespace voxray::detail
