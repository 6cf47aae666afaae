#include "voxray/io/raw_import.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <vector>

#include "consumed_pages.h"
#include "file_kind.h"
#include "raw_messages.h"
#include "raw_samples.h"
#include "raw_size_rule.h"
#include "raw_slice_files.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

using detail::kRawLayoutFlags;

// One slice to read: `path` at byte `offset` (the header, or a slice inside a single file).
struct SliceFileAt {
  std::string path;
  size_t offset = 0;
};

std::string dimsText(long long x, long long y) {
  return std::to_string(x) + "x" + std::to_string(y);
}

std::string ioReason() { return std::error_code(errno, std::generic_category()).message(); }

void validateLayout(const RawLayout& l) {
  const glm::ivec3 d = l.dims;
  if (d.x <= 0 || d.y <= 0 || d.z < 0) {
    throw inputError("raw dimensions " + dimsText(d.x, d.y) + "x" + std::to_string(d.z) +
                     " are not valid: X and Y must be positive, Z positive or 0 (count the "
                     "slices); check --raw-dims");
  }
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(l.spacingMm[i]) || l.spacingMm[i] <= 0) {
      throw inputError("voxel spacing must be positive millimetres, got " +
                       std::to_string(l.spacingMm[i]) + " along axis " + "xyz"[i] +
                       "; check --raw-spacing");
    }
  }
  if (l.headerBytes > (size_t(1) << 40)) {
    throw inputError("a header of " + std::to_string(l.headerBytes) +
                     " bytes is larger than any raw file; check --raw-offset");
  }
  if (!std::isfinite(l.slope) || l.slope == 0 || !std::isfinite(l.intercept)) {
    throw inputError("rescale slope must be a finite non-zero number and intercept finite");
  }
}

// Refuses a volume too large to be real before anything is allocated.
void checkVoxelCount(long long x, long long y, long long z) {
  const size_t slice = size_t(x) * size_t(y);  // both below 2^31: no overflow
  if (slice > kMaxVoxels || (slice > 0 && size_t(z) > kMaxVoxels / slice) || z > INT_MAX) {
    throw inputError("raw dimensions " + dimsText(x, y) + "x" + std::to_string(z) +
                     " are more than the " + std::to_string(kMaxVoxels) +
                     " voxels Voxray accepts; check " + kRawLayoutFlags);
  }
}

size_t fileSize(const std::string& path) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) throw inputError(path + ": cannot read (" + ec.message() + ")");
  return size_t(size);
}

// Slices of a folder or pattern: one file each, all header + one slice long. With a zSlab only
// its files are checked (a rank reading its part does not open the others).
std::vector<SliceFileAt> stackSources(const std::vector<detail::SliceFile>& files,
                                      const RawLayout& l, int& z) {
  if (l.dims.z != 0 && size_t(l.dims.z) != files.size()) {
    throw inputError("the stack has " + std::to_string(files.size()) + " slice files but " +
                     "--raw-dims gives " + std::to_string(l.dims.z) +
                     " slices; give Z = 0 to use every file, or choose them with --raw-range");
  }
  checkVoxelCount(l.dims.x, l.dims.y, (long long)files.size());
  z = int(files.size());
  std::vector<SliceFileAt> sources;
  for (size_t k = 0; k < files.size(); ++k) {
    const auto& f = files[k];
    const bool inSlab = !l.zSlab || (int(k) >= l.zSlab->first && int(k) < l.zSlab->second);
    if (!inSlab) {
      sources.push_back({f.path, l.headerBytes});
      continue;
    }
    const size_t found = fileSize(f.path);
    const size_t expected = detail::rawFileBytes(l, found, true).expected;
    if (found != expected) {
      throw inputError(f.path + ": expected " + std::to_string(expected) + " bytes (" +
                       dimsText(l.dims.x, l.dims.y) + " " + toString(l.type) + " + " +
                       std::to_string(l.headerBytes) + " header), found " + std::to_string(found) +
                       " — check " + kRawLayoutFlags);
    }
    sources.push_back({f.path, l.headerBytes});
  }
  return sources;
}

// Slices of one raw file: header, then Z slices; Z = 0 takes as many as the file holds.
std::vector<SliceFileAt> fileSources(const std::string& path, const RawLayout& l, size_t sliceBytes,
                                     int& z) {
  if (l.range) {
    throw inputError(path + ": --raw-range selects files of a slice stack; a single raw file " +
                     "is read whole");
  }
  const size_t found = fileSize(path);
  std::string layout = " ";  // built by appending: GCC 12 warns falsely on a + chain here
  layout += toString(l.type);
  layout += " + " + std::to_string(l.headerBytes) + " header)";
  const auto rule = detail::rawFileBytes(l, found, false);
  if (l.dims.z == 0 && rule.partialSlice) {
    throw inputError(path + ": " + std::to_string(found) + " bytes are not a whole number of " +
                     dimsText(l.dims.x, l.dims.y) + " slices (" + std::to_string(sliceBytes) +
                     " bytes each" + layout + " — check " + kRawLayoutFlags);
  }
  if (l.dims.z == 0) checkVoxelCount(l.dims.x, l.dims.y, (long long)rule.slices);
  z = int(rule.slices);
  if (found != rule.expected) {
    throw inputError(path + ": expected " + std::to_string(rule.expected) + " bytes (" +
                     dimsText(l.dims.x, l.dims.y) + "x" + std::to_string(z) + layout + ", found " +
                     std::to_string(found) + " — check " + kRawLayoutFlags);
  }
  std::vector<SliceFileAt> sources;
  for (int k = 0; k < z; ++k) sources.push_back({path, l.headerBytes + size_t(k) * sliceBytes});
  return sources;
}

// COUNT blocks of BYTES each, the i-th at S's offset + i * STRIDE, one after another into DEST:
// one open for them all (a point-sampled level reads thousands of rows).
void readBlocks(const SliceFileAt& s, uint8_t* dest, size_t bytes, size_t count, size_t stride) {
  // O_NONBLOCK and fstat: a path swapped for a FIFO after the checks must not hang here.
  const int fd = ::open(s.path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw inputError(s.path + ": cannot read (" + ioReason() + ")");
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    detail::refuseSpecialFile(s.path);
    throw inputError(s.path + ": is not a regular file; save the data to a file and open that");
  }
  for (size_t b = 0; b < count; ++b) {
    uint8_t* to = dest + b * bytes;
    const size_t at = s.offset + b * stride;
    size_t done = 0;
    while (done < bytes) {
      const ssize_t n = ::pread(fd, to + done, bytes - done, off_t(at + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const std::string reason = n < 0 ? ioReason() : "the file ended early";
        ::close(fd);
        throw inputError(s.path + ": cannot read (" + reason + ")");
      }
      done += size_t(n);
    }
  }
  ::close(fd);
}

void readExactly(const SliceFileAt& s, uint8_t* dest, size_t bytes) {
  readBlocks(s, dest, bytes, 1, 0);
}

// INPUT's slices in z order (only listed and checked, not read); Z their count.
std::vector<SliceFileAt> listSources(const std::string& input, const RawLayout& layout, int& z) {
  validateLayout(layout);
  checkVoxelCount(layout.dims.x, layout.dims.y, layout.dims.z);
  const size_t sliceBytes =
      size_t(layout.dims.x) * size_t(layout.dims.y) * sampleBytes(layout.type);
  std::vector<SliceFileAt> sources;
  std::error_code ec;
  if (fs::is_directory(input, ec)) {
    if (layout.range)
      checkVoxelCount(layout.dims.x, layout.dims.y, detail::sliceCount(*layout.range));
    sources = stackSources(detail::listSliceFolder(input, layout.range), layout, z);
  } else if (fs::exists(input, ec)) {
    detail::refuseSpecialFile(input);
    sources = fileSources(input, layout, sliceBytes, z);
  } else if (input.find('%') != std::string::npos) {
    if (layout.range)
      checkVoxelCount(layout.dims.x, layout.dims.y, detail::sliceCount(*layout.range));
    sources = stackSources(detail::listSlicePattern(input, layout.range), layout, z);
  } else {
    throw inputError(input + ": no such file or folder");
  }
  return sources;
}

}  // namespace

Volume importRaw(const std::string& input, const RawLayout& layout) {
  return importRaw(input, layout, RawFeedback{});
}

int rawSliceCount(const std::string& input, const RawLayout& layout) {
  RawLayout listOnly = layout;
  listOnly.zSlab = std::pair<int, int>{0, 0};  // check no file's size: only count them
  int z = 0;
  listSources(input, listOnly, z);
  return z;
}

Volume importRaw(const std::string& input, const RawLayout& layout, const RawFeedback& feedback) {
  const size_t sliceVoxels = size_t(layout.dims.x) * size_t(layout.dims.y);
  const size_t sampleSize = sampleBytes(layout.type);
  const size_t sliceBytes = sliceVoxels * sampleSize;
  int z = 0;
  std::vector<SliceFileAt> sources = listSources(input, layout, z);
  int slabFirst = 0;
  if (layout.zSlab) {
    const auto [first, end] = *layout.zSlab;
    if (first < 0 || end > z || first >= end)
      throw inputError(input + ": slices " + std::to_string(first) + " to " +
                       std::to_string(end - 1) + " were asked for, but it holds slices 0 to " +
                       std::to_string(z - 1));
    sources = std::vector<SliceFileAt>(sources.begin() + first, sources.begin() + end);
    z = end - first;
    slabFirst = first;
  }

  const auto cancelled = [&] { return feedback.cancel && feedback.cancel->load(); };
  const auto report = [&](double fraction, const std::string& what) {
    if (feedback.progress) feedback.progress(fraction, what);
  };

  // Whole slices are read in parallel into one buffer; the rescale needs the full value
  // range before the first voxel can be stored. 16-bit samples are read straight into the
  // volume's voxels and converted in place (each sample is read before its voxel is
  // written), so the peak is one copy of the volume, not two.
  const bool inPlace = sampleBytes(layout.type) == sizeof(int16_t);
  VoxelVector voxels(inPlace ? sliceVoxels * static_cast<size_t>(z) : 0);
  std::vector<uint8_t> rawCopy(inPlace ? 0 : sliceBytes * static_cast<size_t>(z));
  uint8_t* const raw = inPlace ? reinterpret_cast<uint8_t*>(voxels.data()) : rawCopy.data();
  std::vector<detail::ValueStats> stats(static_cast<size_t>(z));
  const detail::SampleDecoding decoding = detail::decodingOf(layout);
  std::atomic<int> slicesRead{0};
  parallelFor(
      size_t(z),
      [&](size_t k) {
        uint8_t* slice = raw + k * sliceBytes;
        readExactly(sources[k], slice, sliceBytes);
        stats[k] = detail::scanSamples(slice, sliceVoxels, decoding);
        const int done = ++slicesRead;
        report(0.9 * done / z,
               "Reading slice " + std::to_string(done) + " of " + std::to_string(z));
      },
      feedback.cancel);
  if (cancelled()) throw cancelledError("loading cancelled");

  detail::ValueStats all;
  for (const auto& s : stats) all.merge(s);
  const detail::Storage storage = detail::chooseStorage(all, decoding);

  Volume v;
  v.dims = {layout.dims.x, layout.dims.y, z};
  v.spacingMm = layout.spacingMm;
  v.direction = layout.direction;
  // A slab starts at its first slice (the whole stack's origin is at slice 0).
  v.originMm = v.direction * glm::dvec3(0.0, 0.0, slabFirst * layout.spacingMm.z);
  v.slope = storage.slope;
  v.intercept = storage.intercept;
  v.unit = rawValueUnit(layout);
  v.sourceType = toString(layout.type);
  if (!storage.warning.empty()) v.warnings.push_back(storage.warning);
  if (inPlace)
    v.voxels = std::move(voxels);  // the buffer (and `raw`) stays where it is
  else
    v.voxels.resize(v.voxelCount());
  report(0.9, "Converting to 16-bit voxels");
  parallelFor(
      size_t(z),
      [&](size_t k) {
        detail::storeSamples(raw + k * sliceBytes, sliceVoxels, decoding, storage,
                             v.voxels.data() + k * sliceVoxels);
        // 8- and 32-bit samples: the read buffer's slice is stored, its pages can go (the
        // peak stays near the volume plus what is read of one slice per thread).
        if (!inPlace) detail::releaseConsumedPages(raw + k * sliceBytes, sliceBytes);
      },
      feedback.cancel);
  if (cancelled()) throw cancelledError("loading cancelled");
  report(1.0, "Loaded " + input);
  return v;
}

struct RawSliceReader::Impl {
  std::vector<SliceFileAt> sources;
  detail::SampleDecoding decoding;
  detail::Storage storage;
  Volume geometry;
  size_t sliceBytes = 0;
  bool scanned = false;
  std::optional<ValueRange> storedRange;  // from the scan
};

RawSliceReader::RawSliceReader(const std::string& input, const RawLayout& layout)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  RawLayout l = layout;
  l.zSlab.reset();
  int z = 0;
  m.sources = listSources(input, l, z);
  m.decoding = detail::decodingOf(l);
  const size_t sliceVoxels = size_t(l.dims.x) * size_t(l.dims.y);
  m.sliceBytes = sliceVoxels * sampleBytes(l.type);
  // The type's whole range, rescaled: when importRaw's choice for it keeps the values as they
  // are, its choice for the actual values (a part of that range) does too.
  const bool integerType = l.type == SampleType::U8 || l.type == SampleType::I16;
  detail::ValueStats typeRange;
  if (integerType) {
    const double a = l.type == SampleType::U8 ? 0.0 : -32768.0;
    const double b = l.type == SampleType::U8 ? 255.0 : 32767.0;
    typeRange.min = std::min(a * l.slope, b * l.slope) + l.intercept;
    typeRange.max = std::max(a * l.slope, b * l.slope) + l.intercept;
    typeRange.any = true;
    typeRange.integral = l.slope == std::floor(l.slope) && l.intercept == std::floor(l.intercept);
  }
  const detail::Storage asIs = detail::chooseStorage(typeRange, m.decoding);
  if (integerType && typeRange.integral && asIs.slope == 1.0 && asIs.intercept == 0.0 &&
      asIs.warning.empty()) {
    m.storage = asIs;
  } else {
    // As importRaw: the storage from every value. One slice at a time (a slice per thread).
    std::vector<detail::ValueStats> stats(static_cast<size_t>(z));
    parallelFor(size_t(z), [&](size_t k) {
      std::vector<uint8_t> slice(m.sliceBytes);
      readExactly(m.sources[k], slice.data(), m.sliceBytes);
      stats[k] = detail::scanSamples(slice.data(), sliceVoxels, m.decoding);
    });
    detail::ValueStats all;
    for (const auto& st : stats) all.merge(st);
    m.storage = detail::chooseStorage(all, m.decoding);
    m.scanned = true;
    // Non-finite samples store the fill value, the lowest; no finite one: all are 0 or fill.
    const double lo = all.any ? all.min : 0.0, hi = all.any ? all.max : 0.0;
    m.storedRange =
        ValueRange{detail::storedValue(lo, m.storage), detail::storedValue(hi, m.storage)};
  }
  Volume& v = m.geometry;
  v.dims = {l.dims.x, l.dims.y, z};
  v.spacingMm = l.spacingMm;
  v.direction = l.direction;
  v.slope = m.storage.slope;
  v.intercept = m.storage.intercept;
  v.unit = rawValueUnit(l);
  v.sourceType = toString(l.type);
  if (!m.storage.warning.empty()) v.warnings.push_back(m.storage.warning);
}

RawSliceReader::~RawSliceReader() = default;

const Volume& RawSliceReader::geometry() const { return impl_->geometry; }
bool RawSliceReader::scanned() const { return impl_->scanned; }
std::optional<ValueRange> RawSliceReader::storedRange() const { return impl_->storedRange; }

void RawSliceReader::readSlices(int first, int end, int16_t* dest) const {
  const Impl& m = *impl_;
  const glm::ivec3 d = m.geometry.dims;
  if (first < 0 || end > d.z || first >= end) {
    std::string text = "slices ";  // appended: GCC 12 warns falsely on a + chain here
    text += std::to_string(first);
    text += " to ";
    text += std::to_string(end - 1);
    text += " are not within the ";
    text += std::to_string(d.z);
    text += " slices of the raw input";
    throw inputError(text);
  }
  const size_t sliceVoxels = size_t(d.x) * size_t(d.y);
  const bool inPlace = m.sliceBytes == sliceVoxels * sizeof(int16_t);
  parallelFor(size_t(end - first), [&](size_t i) {
    int16_t* out = dest + i * sliceVoxels;
    std::vector<uint8_t> samples(inPlace ? 0 : m.sliceBytes);
    uint8_t* raw = inPlace ? reinterpret_cast<uint8_t*>(out) : samples.data();
    readExactly(m.sources[size_t(first) + i], raw, m.sliceBytes);
    // In place for 16-bit samples: each is read before its voxel is written (as importRaw).
    detail::storeSamples(raw, sliceVoxels, m.decoding, m.storage, out);
  });
}

void RawSliceReader::readRows(int z, int firstRow, int rowStep, int rows, int16_t* dest) const {
  const Impl& m = *impl_;
  const glm::ivec3 d = m.geometry.dims;
  if (z < 0 || z >= d.z || firstRow < 0 || rowStep < 1 || rows < 1 ||
      firstRow + size_t(rows - 1) * size_t(rowStep) >= size_t(d.y))
    throw inputError("rows " + std::to_string(firstRow) + " + " + std::to_string(rowStep) + " x " +
                     std::to_string(rows - 1) + " of slice " + std::to_string(z) +
                     " are not within the " + std::to_string(d.x) + "x" + std::to_string(d.y) +
                     "x" + std::to_string(d.z) + " raw input");
  const size_t rowBytes = m.sliceBytes / size_t(d.y);
  const bool inPlace = rowBytes == size_t(d.x) * sizeof(int16_t);
  std::vector<uint8_t> samples(inPlace ? 0 : rowBytes * size_t(rows));
  uint8_t* raw = inPlace ? reinterpret_cast<uint8_t*>(dest) : samples.data();
  SliceFileAt s = m.sources[size_t(z)];
  s.offset += size_t(firstRow) * rowBytes;
  readBlocks(s, raw, rowBytes, size_t(rows), size_t(rowStep) * rowBytes);
  detail::storeSamples(raw, size_t(d.x) * size_t(rows), m.decoding, m.storage, dest);
}

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}  // namespace

std::string rawValueUnit(const RawLayout& layout) {
  return layout.slope != 1.0 || layout.intercept != 0.0 ? "HU" : "value";
}

SampleType parseSampleType(const std::string& s) {
  const std::string t = lower(s);
  if (t == "u8" || t == "uint8") return SampleType::U8;
  if (t == "i16" || t == "int16" || t == "s16") return SampleType::I16;
  if (t == "u16" || t == "uint16") return SampleType::U16;
  if (t == "f32" || t == "float" || t == "float32") return SampleType::F32;
  throw inputError("unknown sample type '" + s + "': use u8, i16, u16 or f32");
}

ByteOrder parseByteOrder(const std::string& s) {
  const std::string t = lower(s);
  if (t == "big" || t == "be") return ByteOrder::Big;
  if (t == "little" || t == "le") return ByteOrder::Little;
  throw inputError("unknown byte order '" + s + "': use big or little");
}

const char* toString(SampleType t) {
  switch (t) {
    case SampleType::U8:
      return "u8";
    case SampleType::I16:
      return "i16";
    case SampleType::U16:
      return "u16";
    case SampleType::F32:
      return "f32";
  }
  return "?";
}

}  // namespace voxray
