#pragma once
// Raw slice stacks as in the seed paper: a folder of numbered slice files, a printf
// pattern with a range, or one raw file. No headers are parsed: the user states the layout.
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "voxray/io/volume.h"

namespace voxray {

enum class SampleType { U8, I16, U16, F32 };
enum class ByteOrder { Little, Big };

struct RawLayout {
  glm::ivec3 dims{0};  // z = 0: taken from the number of slice files
  SampleType type = SampleType::I16;
  ByteOrder order = ByteOrder::Little;
  glm::dvec3 spacingMm{1.0};
  size_t headerBytes = 0;  // skipped at the start of every file
  double slope = 1.0;      // rescale to HU: hu = raw * slope + intercept
  double intercept = 0.0;
  std::optional<std::pair<int, int>> range;  // first-last slice numbers (pattern or folder)
  // Raw data carry no orientation: columns are the LPS directions of the x, y, z index
  // axes (see orientation.h for codes such as "LPI").
  glm::dmat3 direction{1.0};
  // Slices [first, end) of the z index alone (one MPI rank's part, issue 38): only their files
  // (or bytes) are checked and read, and the volume holds just them, its origin moved to
  // slice `first`. The value storage (slope, intercept) is chosen from those slices alone.
  std::optional<std::pair<int, int>> zSlab;
};

// Largest volume accepted before allocating anything (a typo must not allocate 100 GB).
constexpr size_t kMaxVoxels = size_t(2048) * 2048 * 2048;

// INPUT is a folder (slice files ordered by the number in their name, numerically),
// a printf pattern such as "CThead.%d" (needs layout.range), or a single raw file.
// Throws Error (Input) naming the file and what is wrong.
Volume importRaw(const std::string& input, const RawLayout& layout);

// The number of z slices INPUT holds under LAYOUT (layout.dims.z when given), from the file
// listing and sizes alone: nothing is read. Throws Error (Input) as importRaw does.
int rawSliceCount(const std::string& input, const RawLayout& layout);

// Progress and cancellation of a raw load; loadVolume passes LoadOptions' own through.
struct RawFeedback {
  std::function<void(double, const std::string&)> progress;  // 0..1, from worker threads
  const std::atomic<bool>* cancel = nullptr;  // set to true: stops, throws "loading cancelled"
};
Volume importRaw(const std::string& input, const RawLayout& layout, const RawFeedback& feedback);

// The unit of a raw volume's values: raw files carry none. "HU" once the user gave a rescale
// (anything but slope 1, intercept 0: the rescale field and --raw-rescale say "to HU"),
// else "value", so that an MR or an unscaled stack is never labelled HU.
std::string rawValueUnit(const RawLayout& layout);

// A raw input read a range of slices at a time (out-of-core rendering, issue 38): opening lists
// and checks the files as importRaw does; each read preads only its slices, never the whole.
// The values are stored exactly as importRaw stores them. When the sample type's whole range,
// rescaled, fits int16 as it is (u8 and i16 with a whole slope and intercept that keep it
// there, e.g. --raw-rescale 1,0), that storage needs no look at the values; otherwise opening
// reads every slice once (a slice at a time) to choose it as importRaw does.
class RawSliceReader {
 public:
  // Throws Error (Input) as importRaw does. layout.zSlab is not taken.
  RawSliceReader(const std::string& input, const RawLayout& layout);
  ~RawSliceReader();
  RawSliceReader(const RawSliceReader&) = delete;
  RawSliceReader& operator=(const RawSliceReader&) = delete;
  // The volume as importRaw makes it, without voxels.
  const Volume& geometry() const;
  // Slices [FIRST, END) as stored values, i fastest, into DEST. Throws Error (Input) naming the
  // file when it cannot be read.
  void readSlices(int first, int end, int16_t* dest) const;
  // ROWS rows of slice Z (FIRSTROW, FIRSTROW + ROWSTEP, ...), whole, stored as readSlices
  // stores them, into DEST (dims.x * ROWS values): a point-sampled level without reading the
  // rows between (out-of-core's first image from a raw file). Throws Error (Input) as
  // readSlices does, and for rows outside the slice.
  void readRows(int z, int firstRow, int rowStep, int rows, int16_t* dest) const;
  bool scanned() const;  // opening read the values to choose their storage
  // When opening scanned: the stored values' smallest and largest, from that scan (no other
  // read). Else none.
  std::optional<ValueRange> storedRange() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

SampleType parseSampleType(const std::string& s);  // u8, i16, u16, f32
ByteOrder parseByteOrder(const std::string& s);    // big, little
const char* toString(SampleType t);
size_t sampleBytes(SampleType t);  // bytes per sample in the file

}  // namespace voxray
