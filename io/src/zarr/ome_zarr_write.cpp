// An OME-Zarr pyramid written from a SliceSource in z-slabs: level 0's chunks are made from one
// slab of chunk depth at a time, read from the source (or where it holds them in place); each
// slice of a level goes on to the next level, which pairs slices into its own 2x2x2 means and
// writes its own slab when it is full. Memory holds one level-0 slab (int16), one slab and one
// pending slice per further level (about 0.3x a level-0 slab in all when int16, 0.6x as float)
// and the chunks being encoded, never the volume. The group's metadata is written last: it records
// level 0's value range as the slabs passed.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "ome_zarr_meta.h"
#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/parallel.h"
#include "zarr_codecs.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

using Json = nlohmann::json;

struct Format {
  int version = 2;
  bool int16 = true;  // else float32
  ValueRange range;   // int16: level 0's smallest and largest value as written
  zarr::Codec codec;
  size_t typeSize() const { return int16 ? 2 : 4; }
};

// One level of the pyramid being written.
struct LevelOut {
  int index = 0;
  glm::ivec3 dims{0};   // i, j, k
  glm::ivec3 chunk{0};  // chunk edge along i, j, k (the level's dims when smaller)
  fs::path folder;
  // Up to chunk.z slices, exactly the values written: whole numbers in int16 when the level
  // is int16 (half the memory of floats), else floats.
  std::vector<int16_t> slab16;
  std::vector<float> slab;
  int slabZ0 = 0, slabCount = 0;
  std::vector<float> pending;  // a slice of the level above waiting for its pair
  bool hasPending = false;
};

size_t sliceSize(const glm::ivec3& d) { return size_t(d.x) * size_t(d.y); }

void writeFile(const fs::path& file, const std::vector<uint8_t>& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  out.close();
  if (!out) throw outputError(file.string() + ": cannot write (disk full, or no permission?)");
}

void writeJson(const fs::path& file, const Json& j) {
  const std::string text = j.dump(2) + "\n";
  writeFile(file, std::vector<uint8_t>(text.begin(), text.end()));
}

void makeFolder(const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder))
    throw outputError(folder.string() + ": cannot make the folder (" + ec.message() + ")");
}

// Writes the chunks of one z-slab (NZ slices from Z0) of level L. ROW fills N values of the
// slab's slice Z (0-based in the slab), row Y, from column X0.
template <class Row>
void writeSlab(const LevelOut& l, const Format& f, int z0, int nz, const Row& row,
               std::atomic<uint64_t>& bytes, std::atomic<uint64_t>& chunks) {
  const int gx = (l.dims.x + l.chunk.x - 1) / l.chunk.x,
            gy = (l.dims.y + l.chunk.y - 1) / l.chunk.y;
  const size_t chunkSamples = size_t(l.chunk.x) * size_t(l.chunk.y) * size_t(l.chunk.z);
  const int cz = z0 / l.chunk.z;
  parallelFor(size_t(gx) * size_t(gy), [&](size_t c) {
    const int ix = int(c % size_t(gx)), iy = int(c / size_t(gx));
    const int x0 = ix * l.chunk.x, y0 = iy * l.chunk.y;
    const int nx = std::min(l.chunk.x, l.dims.x - x0), ny = std::min(l.chunk.y, l.dims.y - y0);
    // The edge of the array is padded with the fill value (0) to a whole chunk.
    std::vector<uint8_t> raw(chunkSamples * f.typeSize(), 0);
    std::vector<float> values(static_cast<size_t>(nx));
    for (int z = 0; z < nz; ++z)
      for (int y = 0; y < ny; ++y) {
        row(z, y0 + y, x0, nx, values.data());
        const size_t at = (size_t(z) * size_t(l.chunk.y) + size_t(y)) * size_t(l.chunk.x);
        if (f.int16) {
          auto* out = reinterpret_cast<int16_t*>(raw.data()) + at;
          for (int x = 0; x < nx; ++x)
            out[x] = int16_t(std::clamp(values[size_t(x)], -32768.0f, 32767.0f));
        } else {
          std::memcpy(raw.data() + at * 4, values.data(), size_t(nx) * 4);
        }
      }
    if constexpr (std::endian::native == std::endian::big)
      for (size_t i = 0; i < chunkSamples; ++i)
        std::reverse(raw.data() + i * f.typeSize(), raw.data() + (i + 1) * f.typeSize());
    const std::vector<uint8_t> encoded = zarr::encodeChunk(f.codec, raw, f.typeSize());
    fs::path file = l.folder;
    if (f.version == 3) file /= "c";
    file = file / std::to_string(cz) / std::to_string(iy);
    makeFolder(file);
    writeFile(file / std::to_string(ix), encoded);
    bytes += encoded.size();
    ++chunks;
  });
}

class PyramidWriter {
 public:
  PyramidWriter(const Format& f, std::vector<LevelOut>& levels) : f_(f), levels_(levels) {}

  // Slice Z of level L-1 (every slice, in order) for level L.
  void feed(size_t l, const std::vector<float>& slice) {
    if (l >= levels_.size()) return;
    LevelOut& level = levels_[l];
    if (!level.hasPending) {
      level.pending = slice;
      level.hasPending = true;
      return;
    }
    push(l, halve(l, &level.pending, &slice));
    level.hasPending = false;
  }

  // After the last slice of level L-1: the odd last slice alone, the partial slab, and on.
  void finish(size_t l) {
    if (l >= levels_.size()) return;
    LevelOut& level = levels_[l];
    if (level.hasPending) push(l, halve(l, &level.pending, nullptr));
    level.hasPending = false;
    if (level.slabCount > 0) flush(l);
    finish(l + 1);
  }

  std::atomic<uint64_t> bytes{0}, chunks{0};

 private:
  // The 2x2x2 means of slices A and B (B absent: A's 2x2 means) of level L-1, as written.
  std::vector<float> halve(size_t l, const std::vector<float>* a, const std::vector<float>* b) {
    const glm::ivec3 from = levels_[l - 1].dims, to = levels_[l].dims;
    std::vector<float> out(sliceSize(to));
    for (int y = 0; y < to.y; ++y)
      for (int x = 0; x < to.x; ++x) {
        double sum = 0;
        int n = 0;
        for (const std::vector<float>* s : {a, b}) {
          if (!s) continue;
          for (int yy = 2 * y; yy < std::min(2 * y + 2, from.y); ++yy)
            for (int xx = 2 * x; xx < std::min(2 * x + 2, from.x); ++xx, ++n)
              sum += (*s)[size_t(yy) * size_t(from.x) + size_t(xx)];
        }
        const double mean = sum / n;
        out[size_t(y) * size_t(to.x) + size_t(x)] =
            f_.int16 ? float(std::nearbyint(mean)) : float(mean);
      }
    return out;
  }

  void push(size_t l, const std::vector<float>& slice) {
    LevelOut& level = levels_[l];
    const size_t n = sliceSize(level.dims), at = size_t(level.slabCount) * n;
    if (f_.int16)  // means of int16 values, rounded: whole and within int16
      std::transform(slice.begin(), slice.end(), level.slab16.begin() + std::ptrdiff_t(at),
                     [](float value) { return int16_t(value); });
    else
      std::copy(slice.begin(), slice.end(), level.slab.begin() + std::ptrdiff_t(at));
    ++level.slabCount;
    feed(l + 1, slice);
    if (level.slabCount == level.chunk.z) flush(l);
  }

  void flush(size_t l) {
    LevelOut& level = levels_[l];
    const size_t n = sliceSize(level.dims);
    writeSlab(
        level, f_, level.slabZ0, level.slabCount,
        [&](int z, int y, int x0, int count, float* out) {
          const size_t at = size_t(z) * n + size_t(y) * size_t(level.dims.x) + size_t(x0);
          if (f_.int16)
            std::copy(level.slab16.data() + at, level.slab16.data() + at + count, out);
          else
            std::copy(level.slab.data() + at, level.slab.data() + at + count, out);
        },
        bytes, chunks);
    level.slabZ0 += level.slabCount;
    level.slabCount = 0;
  }

  const Format& f_;
  std::vector<LevelOut>& levels_;
};

Json codecJsonV2(const Format& f) {
  switch (f.codec.kind) {
    case zarr::Codec::Kind::Blosc:
      return {{"id", "blosc"},
              {"cname", f.codec.bloscInner},
              {"clevel", f.codec.level},
              {"shuffle", f.codec.bloscShuffle},
              {"blocksize", 0}};
    case zarr::Codec::Kind::Zstd:
      return {{"id", "zstd"}, {"level", f.codec.level}};
    case zarr::Codec::Kind::Gzip:
      return {{"id", "gzip"}, {"level", f.codec.level}};
    default:
      return nullptr;
  }
}

Json codecsJsonV3(const Format& f) {
  Json codecs = Json::array({{{"name", "bytes"}, {"configuration", {{"endian", "little"}}}}});
  switch (f.codec.kind) {
    case zarr::Codec::Kind::Blosc:
      codecs.push_back({{"name", "blosc"},
                        {"configuration",
                         {{"cname", f.codec.bloscInner},
                          {"clevel", f.codec.level},
                          {"shuffle", "shuffle"},
                          {"typesize", f.typeSize()},
                          {"blocksize", 0}}}});
      break;
    case zarr::Codec::Kind::Zstd:
      codecs.push_back(
          {{"name", "zstd"}, {"configuration", {{"level", f.codec.level}, {"checksum", false}}}});
      break;
    case zarr::Codec::Kind::Gzip:
      codecs.push_back({{"name", "gzip"}, {"configuration", {{"level", f.codec.level}}}});
      break;
    default:
      break;
  }
  return codecs;
}

void writeArrayMeta(const LevelOut& l, const Format& f) {
  const Json shape = {l.dims.z, l.dims.y, l.dims.x}, chunks = {l.chunk.z, l.chunk.y, l.chunk.x};
  if (f.version == 2) {
    writeJson(l.folder / ".zarray", {{"zarr_format", 2},
                                     {"shape", shape},
                                     {"chunks", chunks},
                                     {"dtype", f.int16 ? "<i2" : "<f4"},
                                     {"compressor", codecJsonV2(f)},
                                     {"fill_value", 0},
                                     {"order", "C"},
                                     {"filters", nullptr},
                                     {"dimension_separator", "/"}});
    return;
  }
  writeJson(l.folder / "zarr.json",
            {{"zarr_format", 3},
             {"node_type", "array"},
             {"shape", shape},
             {"data_type", f.int16 ? "int16" : "float32"},
             {"chunk_grid", {{"name", "regular"}, {"configuration", {{"chunk_shape", chunks}}}}},
             {"chunk_key_encoding", {{"name", "default"}, {"configuration", {{"separator", "/"}}}}},
             {"fill_value", 0},
             {"codecs", codecsJsonV3(f)},
             {"attributes", Json::object()},
             {"dimension_names", {"z", "y", "x"}}});
}

void writeGroupMeta(const fs::path& root, const Volume& v, const Format& f,
                    const std::vector<LevelOut>& levels) {
  // The translation is the origin in the volume's own axes: LPS origin = direction * it.
  const glm::dvec3 t0 = glm::transpose(v.direction) * v.originMm;
  Json datasets = Json::array();
  for (const LevelOut& l : levels) {
    const double f2 = std::ldexp(1.0, l.index);
    const glm::dvec3 s = v.spacingMm * f2, t = t0 + v.spacingMm * ((f2 - 1.0) / 2.0);
    datasets.push_back({{"path", std::to_string(l.index)},
                        {"coordinateTransformations",
                         {{{"type", "scale"}, {"scale", {s.z, s.y, s.x}}},
                          {{"type", "translation"}, {"translation", {t.z, t.y, t.x}}}}}});
  }
  Json axes = Json::array();
  for (const char* name : {"z", "y", "x"})
    axes.push_back({{"name", name}, {"type", "space"}, {"unit", "millimeter"}});
  Json multiscale = {
      {"name", "volume"},
      {"axes", axes},
      {"datasets", datasets},
      {"type", "mean"},
      {"metadata", {{"method", "2x2x2 mean of the level before (voxray-cli convert)"}}}};
  Json direction = Json::array();
  for (int c = 0; c < 3; ++c)
    direction.push_back({v.direction[c].x, v.direction[c].y, v.direction[c].z});
  Json voxray = {{"direction", direction},
                 {"unit", v.unit},
                 {"modality", v.modality},
                 {"note",
                  "direction: LPS unit vectors of x, y, z (columns); the LPS "
                  "origin is direction * translation"}};
  // Out-of-core rendering maps its colour table over level 0's value range before it has
  // read level 0 (voxray/engine/out_of_core.h): two numbers here spare it a pass over 8 GiB.
  if (f.int16) voxray["level0-range"] = {f.range.min, f.range.max};
  if (f.version == 2) {
    multiscale["version"] = "0.4";
    writeJson(root / ".zgroup", {{"zarr_format", 2}});
    writeJson(root / ".zattrs", {{"multiscales", {multiscale}}, {zarr::kVoxrayBlock, voxray}});
    return;
  }
  writeJson(root / "zarr.json", {{"zarr_format", 3},
                                 {"node_type", "group"},
                                 {"attributes",
                                  {{"ome", {{"version", "0.5"}, {"multiscales", {multiscale}}}},
                                   {zarr::kVoxrayBlock, voxray}}}});
}

// Smallest and largest of N stored values at S, a slice a thread.
ValueRange rangeOf(const int16_t* s, size_t slices, size_t sliceVoxels) {
  std::vector<ValueRange> r(slices);
  parallelFor(slices, [&](size_t k) {
    int16_t lo = INT16_MAX, hi = INT16_MIN;
    for (const int16_t* p = s + k * sliceVoxels; p != s + (k + 1) * sliceVoxels; ++p) {
      lo = std::min(lo, *p);
      hi = std::max(hi, *p);
    }
    r[k] = {lo, hi};
  });
  ValueRange all = r.front();
  for (const ValueRange& x : r) all = {std::min(all.min, x.min), std::max(all.max, x.max)};
  return all;
}

// The stored values' range: the source's, else one pass over its slices, STEP at a time.
ValueRange storedRangeOf(SliceSource& source, int step) {
  if (const std::optional<ValueRange> r = source.storedRange()) return *r;
  const Volume& g = source.geometry();
  const size_t n = sliceSize(g.dims);
  std::vector<int16_t> slab;
  std::optional<ValueRange> all;
  for (int z0 = 0; z0 < g.dims.z; z0 += step) {
    const int nz = std::min(step, g.dims.z - z0);
    slab.resize(size_t(nz) * n);
    source.readSlices(z0, z0 + nz, slab.data());
    const ValueRange r = rangeOf(slab.data(), size_t(nz), n);
    all = all ? ValueRange{std::min(all->min, r.min), std::max(all->max, r.max)} : r;
  }
  return all.value_or(ValueRange{});
}

// Physical values are whole numbers that fit int16: HU as they are. Otherwise float32. Only a
// whole intercept other than 0 needs the stored range (stored + intercept may pass int16).
bool fitsInt16(SliceSource& source, int step) {
  const Volume& v = source.geometry();
  if (v.slope != 1.0 || v.intercept != std::floor(v.intercept)) return false;
  if (v.intercept == 0.0) return true;
  const ValueRange r = storedRangeOf(source, step);
  return r.min + v.intercept >= -32768.0 && r.max + v.intercept <= 32767.0;
}

}  // namespace

ZarrCodec parseZarrCodec(const std::string& name) {
  if (name == "blosc-zstd") return ZarrCodec::BloscZstd;
  if (name == "zstd") return ZarrCodec::Zstd;
  if (name == "gzip") return ZarrCodec::Gzip;
  if (name == "none") return ZarrCodec::None;
  throw inputError("--codec: '" + name + "' is not one of blosc-zstd, zstd, gzip, none");
}

ZarrWriteResult writeOmeZarr(const Volume& v, const std::string& path,
                             const ZarrWriteOptions& options) {
  const std::unique_ptr<SliceSource> source = volumeSliceSource(v);
  return writeOmeZarr(*source, path, options);
}

ZarrWriteResult writeOmeZarr(SliceSource& source, const std::string& path,
                             const ZarrWriteOptions& options) {
  const Volume& v = source.geometry();
  if (options.zarrVersion != 2 && options.zarrVersion != 3)
    throw inputError("--zarr-version: " + std::to_string(options.zarrVersion) +
                     " is neither 2 (NGFF 0.4) nor 3 (NGFF 0.5)");
  if (options.chunk < 8 || options.chunk > 512)
    throw inputError("--chunks: " + std::to_string(options.chunk) +
                     " is outside 8 to 512 voxels (64 suits most volumes)");
  if (options.levels < 0 || options.levels > 16)
    throw inputError("--levels: " + std::to_string(options.levels) + " is outside 1 to 16");
  if (v.voxelCount() == 0) throw inputError("the volume is empty; nothing to write");
  std::error_code ec;
  const fs::path target = fs::absolute(path);
  if (fs::exists(fs::symlink_status(target, ec)) && !options.force)
    throw outputError(path +
                      ": exists already; choose another name, or give --force to replace "
                      "it");
  if (!fs::is_directory(target.parent_path(), ec))
    throw outputError(path + ": its folder " + target.parent_path().string() + " does not exist");

  Format f;
  f.version = options.zarrVersion;
  f.int16 = fitsInt16(source, std::min(options.chunk, v.dims.z));
  switch (options.codec) {
    case ZarrCodec::BloscZstd:
      f.codec.kind = zarr::Codec::Kind::Blosc;
      f.codec.bloscInner = "zstd";
      f.codec.level = 5;
      break;
    case ZarrCodec::Zstd:
      f.codec.kind = zarr::Codec::Kind::Zstd;
      f.codec.level = 3;
      break;
    case ZarrCodec::Gzip:
      f.codec.kind = zarr::Codec::Kind::Gzip;
      f.codec.level = 5;
      break;
    case ZarrCodec::None:
      f.codec.kind = zarr::Codec::Kind::None;
      break;
  }

  // Written beside the target and renamed: a reader never sees half a pyramid.
  const fs::path temp = target.parent_path() /
                        (target.filename().string() + ".partial-" + std::to_string(::getpid()));
  fs::remove_all(temp, ec);
  makeFolder(temp);
  std::vector<LevelOut> levels;
  try {
    glm::ivec3 dims = v.dims;
    for (int l = 0;; ++l) {
      LevelOut level;
      level.index = l;
      level.dims = dims;
      level.chunk = glm::min(dims, glm::ivec3(options.chunk));
      level.folder = temp / std::to_string(l);
      const size_t slab = l > 0 ? sliceSize(dims) * size_t(level.chunk.z) : 0;
      if (f.int16)
        level.slab16.resize(slab);
      else
        level.slab.resize(slab);
      makeFolder(level.folder);
      writeArrayMeta(level, f);
      levels.push_back(std::move(level));
      const bool more =
          options.levels ? l + 1 < options.levels : std::max(dims.x, dims.y) > options.chunk;
      if (!more) break;
      dims = (dims + 1) / 2;
    }

    PyramidWriter pyramid(f, levels);
    const LevelOut& base = levels[0];
    const size_t n = sliceSize(v.dims);
    std::vector<int16_t> read;  // level 0's slab when the source does not hold it in place
    std::vector<float> slice(n);
    std::optional<ValueRange> range;  // of the stored values, as the slabs pass
    for (int z0 = 0; z0 < v.dims.z; z0 += base.chunk.z) {
      const int nz = std::min(base.chunk.z, v.dims.z - z0);
      if (options.progress)
        options.progress(double(z0) / v.dims.z, "Writing slices " + std::to_string(z0) + "-" +
                                                    std::to_string(z0 + nz - 1));
      const int16_t* stored = source.slicesInPlace(z0);
      if (!stored) {
        read.resize(size_t(nz) * n);
        source.readSlices(z0, z0 + nz, read.data());
        stored = read.data();
      }
      const auto physical = [&](size_t at) { return float(stored[at] * v.slope + v.intercept); };
      if (f.int16) {
        const ValueRange r = rangeOf(stored, size_t(nz), n);
        range = range ? ValueRange{std::min(range->min, r.min), std::max(range->max, r.max)} : r;
      }
      writeSlab(
          base, f, z0, nz,
          [&](int z, int y, int x0, int count, float* out) {
            const size_t at =
                (size_t(z) * size_t(v.dims.y) + size_t(y)) * size_t(v.dims.x) + size_t(x0);
            for (int x = 0; x < count; ++x) out[x] = physical(at + size_t(x));
          },
          pyramid.bytes, pyramid.chunks);
      for (int z = 0; z < nz; ++z) {
        for (size_t i = 0; i < n; ++i) slice[i] = physical(size_t(z) * n + i);
        pyramid.feed(1, slice);
      }
    }
    pyramid.finish(1);
    // int16: the values fit, so level 0's range is the stored one plus the intercept.
    if (f.int16 && range)
      f.range = {int16_t(range->min + v.intercept), int16_t(range->max + v.intercept)};
    writeGroupMeta(temp, v, f, levels);

    if (fs::exists(fs::symlink_status(target, ec))) {
      const fs::path old = target.parent_path() /
                           (target.filename().string() + ".replaced-" + std::to_string(::getpid()));
      fs::rename(target, old);
      fs::rename(temp, target);
      fs::remove_all(old, ec);
    } else {
      fs::rename(temp, target);
    }
    ZarrWriteResult result;
    for (const LevelOut& l : levels) result.dims.push_back(l.dims);
    result.dataType = f.int16 ? "int16" : "float32";
    result.chunks = pyramid.chunks;
    result.bytes = pyramid.bytes;
    if (options.progress) options.progress(1.0, "Written");
    return result;
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(temp, ec);
    throw outputError(path + ": cannot write (" + e.what() + ")");
  } catch (...) {
    fs::remove_all(temp, ec);
    throw;
  }
}

}  // namespace voxray
