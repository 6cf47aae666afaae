// OME-Zarr into a Volume: the multiscales metadata gives the level's array and its geometry;
// the chunks are decoded in parallel straight into the samples of the 3D volume; the samples
// become 16-bit voxels by raw input's rule (raw_samples.h: exact when they fit int16).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <mutex>
#include <set>
#include <sstream>

#include "../file_kind.h"
#include "ome_zarr_meta.h"
#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/parallel.h"
#include "voxray/io/raw_import.h"
#include "zarr_array.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

using zarr::ArrayMeta;

void report(const LoadOptions& o, double fraction, const std::string& what) {
  if (o.progress) o.progress(fraction, what);
}

void throwIfCancelled(const LoadOptions& o) {
  if (o.cancel && o.cancel->load()) throw cancelledError("loading cancelled");
}

void swapBytes(uint8_t* p, size_t count, size_t size) {
  for (size_t i = 0; i < count; ++i, p += size) std::reverse(p, p + size);
}

// One sample of VALUE in KIND, native byte order (a missing chunk's fill).
std::vector<uint8_t> sampleOf(double value, detail::SampleKind kind) {
  std::vector<uint8_t> out(detail::sampleBytes(kind));
  auto put = [&](auto x) { std::memcpy(out.data(), &x, sizeof x); };
  using K = detail::SampleKind;
  const bool finite = std::isfinite(value);
  switch (kind) {
    case K::U8:
      put(uint8_t(finite ? value : 0));
      break;
    case K::I8:
      put(int8_t(finite ? value : 0));
      break;
    case K::U16:
      put(uint16_t(finite ? value : 0));
      break;
    case K::I16:
      put(int16_t(finite ? value : 0));
      break;
    case K::U32:
      put(uint32_t(finite ? value : 0));
      break;
    case K::I32:
      put(int32_t(finite ? value : 0));
      break;
    case K::F32:
      put(float(value));
      break;
    case K::F64:
      put(value);
      break;
  }
  return out;
}

// The chunk KEY (below the array) into DATA; false when the store has none.
bool readChunk(ZarrStore& store, const ArrayMeta& m, const std::string& key,
               std::vector<uint8_t>& data, uint64_t maxBytes) {
  return store.read(m.storeKey(key), data, maxBytes,
                    "the chunk has more than " + std::to_string(maxBytes) +
                        " bytes, more than any encoding of it takes; the Zarr array is damaged");
}

struct ChunkCount {
  size_t missing = 0, total = 0;
  std::vector<uint64_t> missingAt;  // the missing chunks' z, y, x grid index, x fastest
};

// Slices [ZFIRST, ZEND) (all when ZEND is 0) of the array's 3D volume at index 0 of any leading
// (t, c) axes into DEST, as samples of its own type in native byte order, i fastest. The
// spatial axes are the last three (z, y, x). Only the chunks whose z range meets the slices are
// read; they are decoded in parallel, each writing its own box of DEST.
ChunkCount readSpatial(ZarrStore& store, const ArrayMeta& m, const LoadOptions& options,
                       uint8_t* dest, uint64_t zFirst = 0, uint64_t zEnd = 0) {
  const size_t n = m.shape.size(), lead = n - 3, ts = m.typeSize();
  const uint64_t X = m.shape[n - 1], Y = m.shape[n - 2], Z = m.shape[n - 3];
  const uint64_t cx = m.chunks[n - 1], cy = m.chunks[n - 2], cz = m.chunks[n - 3];
  if (zEnd == 0) zEnd = Z;
  const uint64_t gx = (X + cx - 1) / cx, gy = (Y + cy - 1) / cy;
  const uint64_t gz0 = zFirst / cz, gz = (zEnd + cz - 1) / cz - gz0;
  const uint64_t chunkBytes = m.chunkSamples() * ts;
  // Any encoding of a chunk (Blosc, zstd, deflate) is below twice its size plus headers.
  const uint64_t maxFile = chunkBytes * 2 + 4096 + (m.crc32cSuffix ? 4 : 0);
  ChunkCount out;
  out.total = size_t(gx * gy * gz);
  const std::vector<uint8_t> fill = sampleOf(m.fill, m.kind);
  std::atomic<size_t> missing{0}, done{0};
  std::mutex missingLock;
  parallelFor(
      out.total,
      [&](size_t c) {
        const uint64_t ix = c % gx, iy = (c / gx) % gy, iz = gz0 + c / (gx * gy);
        std::vector<uint64_t> index(lead, 0);
        index.insert(index.end(), {iz, iy, ix});
        const std::string key = m.chunkKey(index);
        const uint64_t x0 = ix * cx, y0 = iy * cy, z0 = iz * cz;
        const uint64_t nx = std::min(cx, X - x0), ny = std::min(cy, Y - y0);
        // The chunk's slices within [zFirst, zEnd): from zs (of the chunk) to ze.
        const uint64_t zs = std::max(z0, zFirst) - z0, ze = std::min(z0 + cz, zEnd) - z0;
        std::vector<uint8_t> data, raw;
        if (!readChunk(store, m, key, data, maxFile)) {
          ++missing;
          {
            std::lock_guard<std::mutex> hold(missingLock);
            out.missingAt.push_back((iz * gy + iy) * gx + ix);
          }
          for (uint64_t z = zs; z < ze; ++z)
            for (uint64_t y = 0; y < ny; ++y) {
              uint8_t* row = dest + (((z0 + z - zFirst) * Y + y0 + y) * X + x0) * ts;
              for (uint64_t x = 0; x < nx; ++x) std::memcpy(row + x * ts, fill.data(), ts);
            }
        } else {
          const std::string where = store.where(m.storeKey(key));
          if (m.crc32cSuffix) {
            if (data.size() < 4) throw inputError(where + ": the chunk is truncated (no checksum)");
            data.resize(data.size() - 4);  // the checksum is not verified (zlib has no CRC-32C)
          }
          raw.resize(size_t(chunkBytes));
          zarr::decodeChunk(m.codec, data, raw, ts, where);
          if (m.swap) swapBytes(raw.data(), raw.size() / ts, ts);
          // Leading indices are 0: the 3D box starts the chunk, rows of cx samples.
          for (uint64_t z = zs; z < ze; ++z)
            for (uint64_t y = 0; y < ny; ++y)
              std::memcpy(dest + (((z0 + z - zFirst) * Y + y0 + y) * X + x0) * ts,
                          raw.data() + ((z * cy + y) * cx) * ts, size_t(nx * ts));
        }
        const size_t k = ++done;
        if (k % 64 == 0) report(options, 0.9 * double(k) / double(out.total), "Reading chunks");
      },
      options.cancel);
  throwIfCancelled(options);
  out.missing = missing;
  return out;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

namespace zarr {

void checkLevelIndex(const Pyramid& pyramid, int index, const std::string& where) {
  if (index < 0 || size_t(index) >= pyramid.levels.size())
    throw inputError(where + ": --level " + std::to_string(index) +
                     " is out of range: the pyramid has " + std::to_string(pyramid.levels.size()) +
                     " level" + (pyramid.levels.size() == 1 ? "" : "s") + " (0 to " +
                     std::to_string(pyramid.levels.size() - 1) + ")");
}

Volume describeLevel(const Pyramid& pyramid, int index, const ArrayMeta& m,
                     const std::string& where) {
  checkLevelIndex(pyramid, index, where);
  const Level& level = pyramid.levels[size_t(index)];
  if (m.shape.size() != pyramid.axes)
    throw inputError(m.metadataFile + ": the array has " + std::to_string(m.shape.size()) +
                     " dimensions but the multiscales metadata names " +
                     std::to_string(pyramid.axes) + " axes; the metadata is damaged");
  const size_t n = m.shape.size();
  Volume v;
  v.warnings = pyramid.warnings;
  for (size_t a = 0; a + 3 < n; ++a)
    if (m.shape[a] > 1)
      v.warnings.push_back("the array has " + std::to_string(m.shape[a]) + " along its '" +
                           pyramid.axisNames[a] + "' axis; Voxray shows the first");
  const std::array<uint64_t, 3> dims = {m.shape[n - 1], m.shape[n - 2], m.shape[n - 3]};
  uint64_t count = 1;
  for (uint64_t d : dims) {
    if (d > kMaxVoxels || count > kMaxVoxels / d)
      throw inputError(m.metadataFile + ": the shape " + nlohmann::json(m.shape).dump() +
                       " has more voxels than Voxray can hold (at most " +
                       std::to_string(kMaxVoxels) + "); open a coarser level with --level");
    count *= d;
  }
  for (int i = 0; i < 3; ++i)
    if (dims[size_t(i)] > uint64_t(std::numeric_limits<int>::max()))
      throw inputError(m.metadataFile + ": the shape " + nlohmann::json(m.shape).dump() + " has " +
                       std::to_string(dims[size_t(i)]) + " voxels along " + "xyz"[i] +
                       "; Voxray holds at most " + std::to_string(std::numeric_limits<int>::max()) +
                       " along an axis");
  v.dims = glm::ivec3(int(dims[0]), int(dims[1]), int(dims[2]));
  v.spacingMm = level.spacingMm;
  v.direction = pyramid.direction;
  v.originMm = pyramid.direction * level.translationMm;
  const glm::dvec3 extent = v.spacingMm * glm::dvec3(v.dims);
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(v.originMm[i]) || !std::isfinite(extent[i]))
      throw inputError(m.metadataFile + ": level " + std::to_string(index) +
                       " reaches beyond any length (its origin or extent along " + "xyz"[i] +
                       " passes 1e308 mm); the multiscales metadata is damaged");
  v.unit = pyramid.unit;
  v.modality = pyramid.modality;
  v.sourceType = kindName(m.kind);
  return v;
}

}  // namespace zarr

Volume importOmeZarr(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw inputError(path + ": no such folder");
  detail::refuseSpecialFile(path);
  report(options, 0.0, "Reading " + fs::path(path).filename().string());
  return importOmeZarr(*zarrFolderStore(path), options);
}

Volume importOmeZarr(ZarrStore& store, const LoadOptions& options) {
  const zarr::Pyramid pyramid = zarr::readPyramid(store);
  zarr::checkLevelIndex(pyramid, options.level, store.where(""));
  const ArrayMeta m =
      zarr::readArrayMeta(store, pyramid.levels[size_t(options.level)].path, pyramid.format);
  Volume v = zarr::describeLevel(pyramid, options.level, m, store.where(""));
  const std::array<uint64_t, 3> dims = {uint64_t(v.dims.x), uint64_t(v.dims.y), uint64_t(v.dims.z)};
  v.voxels.resize(v.voxelCount());
  // int16 chunks go straight into the voxels (stored = value); other types through a buffer
  // of their own and raw input's storage rule.
  std::vector<uint8_t> samples;
  if (m.kind != detail::SampleKind::I16) samples.resize(v.voxelCount() * m.typeSize());
  const ChunkCount s =
      readSpatial(store, m, options,
                  samples.empty() ? reinterpret_cast<uint8_t*>(v.voxels.data()) : samples.data());
  if (s.missing)
    v.warnings.push_back(std::to_string(s.missing) + " of " + std::to_string(s.total) +
                         " chunks are missing in " + store.where(m.path) +
                         "; they show the fill value " + number(m.fill));
  if (!samples.empty()) {
    detail::SampleDecoding decoding;
    decoding.kind = m.kind;
    const size_t sliceVoxels = size_t(dims[0] * dims[1]), slices = size_t(dims[2]);
    const size_t sliceBytes = sliceVoxels * m.typeSize();
    std::vector<detail::ValueStats> stats(slices);
    parallelFor(
        slices,
        [&](size_t k) {
          stats[k] = detail::scanSamples(samples.data() + k * sliceBytes, sliceVoxels, decoding);
        },
        options.cancel);
    throwIfCancelled(options);
    detail::ValueStats all;
    for (const auto& st : stats) all.merge(st);
    const detail::Storage storage = detail::chooseStorage(all, decoding);
    v.slope = storage.slope;
    v.intercept = storage.intercept;
    if (!storage.warning.empty()) v.warnings.push_back(storage.warning);
    report(options, 0.95, "Converting to 16-bit voxels");
    parallelFor(
        slices,
        [&](size_t k) {
          detail::storeSamples(samples.data() + k * sliceBytes, sliceVoxels, decoding, storage,
                               v.voxels.data() + k * sliceVoxels);
        },
        options.cancel);
    throwIfCancelled(options);
  }
  report(options, 1.0, "Loaded");
  return v;
}

struct OmeZarrLevel::Impl {
  ZarrStore& store;
  zarr::Pyramid pyramid;
  ArrayMeta meta;
  Volume geometry;
  std::set<uint64_t> missing;  // chunks found missing: a chunk two reads meet counts once
  uint64_t read = 0;
  int level = 0;
  std::vector<uint8_t> samples;  // an 8-bit range before it widens to int16
  explicit Impl(ZarrStore& s) : store(s) {}
};

OmeZarrLevel::OmeZarrLevel(ZarrStore& store, int level) : impl_(std::make_unique<Impl>(store)) {
  Impl& m = *impl_;
  m.pyramid = zarr::readPyramid(store);
  zarr::checkLevelIndex(m.pyramid, level, store.where(""));
  m.level = level;
  m.meta = zarr::readArrayMeta(store, m.pyramid.levels[size_t(level)].path, m.pyramid.format);
  m.geometry = zarr::describeLevel(m.pyramid, level, m.meta, store.where(""));
  using K = detail::SampleKind;
  if (m.meta.kind != K::I16 && m.meta.kind != K::U8 && m.meta.kind != K::I8)
    throw inputError(m.meta.metadataFile + ": the array holds " + m.meta.dataType +
                     " values; Voxray streams int16 and 8-bit arrays only (their values are the "
                     "voxels). Convert it once with voxray-cli convert INPUT -o OUTPUT.ome.zarr, "
                     "or render it without --memory-budget");
}

OmeZarrLevel::~OmeZarrLevel() = default;

const Volume& OmeZarrLevel::geometry() const { return impl_->geometry; }
int OmeZarrLevel::levelCount() const { return int(impl_->pyramid.levels.size()); }
int OmeZarrLevel::chunkSlices() const {
  const auto& c = impl_->meta.chunks;
  return int(c[c.size() - 3]);
}
size_t OmeZarrLevel::missingChunks() const { return impl_->missing.size(); }
uint64_t OmeZarrLevel::chunksRead() const { return impl_->read; }
std::optional<ValueRange> OmeZarrLevel::statedRange() const {
  if (impl_->level != 0) return std::nullopt;
  return impl_->pyramid.level0Range;
}

void OmeZarrLevel::readSlices(int first, int end, int16_t* dest) {
  Impl& m = *impl_;
  const glm::ivec3 d = m.geometry.dims;
  if (first < 0 || end > d.z || first >= end)
    throw inputError("slices " + std::to_string(first) + " to " + std::to_string(end - 1) +
                     " are not within the " + std::to_string(d.z) + " slices of " +
                     m.store.where(m.meta.path));
  const size_t count = size_t(d.x) * size_t(d.y) * size_t(end - first);
  const bool wide = m.meta.kind == detail::SampleKind::I16;
  if (!wide) m.samples.resize(count);
  const ChunkCount c = readSpatial(m.store, m.meta, LoadOptions{},
                                   wide ? reinterpret_cast<uint8_t*>(dest) : m.samples.data(),
                                   uint64_t(first), uint64_t(end));
  m.missing.insert(c.missingAt.begin(), c.missingAt.end());
  m.read += c.total;
  if (!wide) {
    const bool isSigned = m.meta.kind == detail::SampleKind::I8;
    for (size_t i = 0; i < count; ++i)
      dest[i] = isSigned ? int16_t(int8_t(m.samples[i])) : int16_t(m.samples[i]);
    std::vector<uint8_t>().swap(m.samples);  // released: a range's bytes, not held between reads
  }
}

}  // namespace voxray
