#include "voxray/engine/slab_source.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "voxray/engine/coarse_level.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/raw_import.h"
#ifdef VOXRAY_HAS_ZARR
#include "voxray/io/ome_zarr.h"
#endif

namespace voxray {

namespace {

// coarseLevel of G's volume without holding it: each coarse slice from its FACTOR slices, read
// by READ(first, end, dest). RANGE (when given): the stored values' smallest and largest.
Volume streamedMean(const Volume& g, int factor,
                    const std::function<void(int, int, int16_t*)>& read,
                    ValueRange* range = nullptr, const std::atomic<bool>* stop = nullptr) {
  Volume slab = g;
  Volume c;
  int lo = INT16_MAX, hi = INT16_MIN;
  for (int z0 = 0; z0 < g.dims.z; z0 += factor) {
    if (stop && *stop) throw cancelledError("the coarse level's pass was stopped");
    const int z1 = std::min(g.dims.z, z0 + factor);
    slab.dims.z = z1 - z0;
    slab.voxels.resize(slab.voxelCount());
    read(z0, z1, slab.voxels.data());
    if (range) {
      const auto [a, b] = std::minmax_element(slab.voxels.begin(), slab.voxels.end());
      lo = std::min<int>(lo, *a);
      hi = std::max<int>(hi, *b);
    }
    Volume one = coarseLevel(slab, factor);  // x, y as the whole's; one slice
    if (c.voxels.empty()) {
      c = withoutVoxels(g);
      c.dims = (g.dims + factor - 1) / factor;
      c.spacingMm = glm::dvec3(g.dims) * g.spacingMm / glm::dvec3(c.dims);
      c.originMm = g.originMm + g.direction * ((c.spacingMm - g.spacingMm) * 0.5);
      c.voxels.resize(c.voxelCount());
    }
    std::copy(one.voxels.begin(), one.voxels.end(),
              c.voxels.begin() + ptrdiff_t(size_t(z0 / factor) * one.voxels.size()));
  }
  if (range) *range = {int16_t(lo), int16_t(hi)};
  return c;
}

// The level coarseLevel(G, FACTOR) would have (dims, spacing, origin: the full box), without
// voxels.
Volume coarseGeometry(const Volume& g, int factor) {
  Volume c = withoutVoxels(g);
  c.dims = (g.dims + factor - 1) / factor;
  c.spacingMm = glm::dvec3(g.dims) * g.spacingMm / glm::dvec3(c.dims);
  c.originMm = g.originMm + g.direction * ((c.spacingMm - g.spacingMm) * 0.5);
  return c;
}

// The full volume's voxel nearest the centre of coarse voxel I along an axis of N voxels, CN
// coarse ones (coarseGeometry: coarse voxel i spans full voxels [i, i + 1) * N / CN).
int nearestFull(int i, int n, int cn) {
  const double at = (double(i) + 0.5) * double(n) / double(cn) - 0.5;
  return std::clamp(int(std::lround(at)), 0, n - 1);
}

// A thread of a source's own making its coarse level (SlabSource::startCoarse): started once,
// waited for by get(), stopped by the destructor (the pass checks STOP between reads).
class CoarseThread {
 public:
  ~CoarseThread() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  // MAKE(stop) on the thread, unless started already.
  void start(std::function<Volume(const std::atomic<bool>&)> make) {
    std::lock_guard lock(mutex_);
    if (started_) return;
    started_ = true;
    thread_ = std::thread([this, make = std::move(make)] {
      try {
        made_ = make(stop_);
      } catch (...) {
        error_ = std::current_exception();
      }
      done_ = true;
    });
  }
  bool started() const { return started_; }
  bool done() const { return done_; }
  // The level, waiting for the thread; rethrows what it threw.
  Volume& get() {
    std::lock_guard lock(mutex_);
    if (thread_.joinable()) thread_.join();
    if (error_) std::rethrow_exception(error_);
    return made_;
  }

 private:
  std::mutex mutex_;
  std::thread thread_;
  std::atomic<bool> started_{false}, done_{false}, stop_{false};
  std::exception_ptr error_;
  Volume made_;
};

// A raw file or slice stack read with pread a range of slices at a time (RawSliceReader); its
// coarse level the 4x box mean made in one streamed pass, which also finds the value range;
// its quick level point samples (SlabSource::quickLevel), shown until that pass ends.
class RawSource : public SlabSource {
 public:
  RawSource(const std::string& input, const RawLayout& layout)
      : reader_(input, layout), input_(input) {}
  const Volume& geometry() const override { return reader_.geometry(); }
  void readSlices(int first, int end, int16_t* dest) override {
    reader_.readSlices(first, end, dest);
  }
  int preferredSlices() const override { return 0; }
  std::optional<ValueRange> statedRange() const override {
    if (!pass_.done() || !range_) return std::nullopt;  // written by the pass's thread
    return range_;
  }
  const Volume* quickLevel() override {
    if (!quick_) quick_ = pointSampled();
    return &*quick_;
  }
  glm::ivec3 coarseDims() override { return (reader_.geometry().dims + 3) / 4; }
  void startCoarse() override {
    pass_.start([this](const std::atomic<bool>& stop) {
      ValueRange r;
      Volume c = streamedMean(
          reader_.geometry(), 4, [&](int a, int b, int16_t* d) { reader_.readSlices(a, b, d); }, &r,
          &stop);
      range_ = r;
      return c;
    });
  }
  bool coarseReady() const override { return pass_.done(); }
  const Volume& coarse() override {
    startCoarse();
    return pass_.get();
  }
  std::string describe() const override { return "raw " + input_ + ", read on demand"; }

 private:
  // Every F-th voxel (F = 4, 8, 16, ...: the first with at most kQuickVoxels), the one nearest
  // each coarse voxel's centre: F^2 fewer rows read than slices' bytes, F fewer slices.
  Volume pointSampled() const {
    const Volume& g = reader_.geometry();
    int f = 4;
    while (f < 1 << 14 && size_t(coarseGeometry(g, f).voxelCount()) > kQuickVoxels) f *= 2;
    Volume q = coarseGeometry(g, f);
    q.voxels.resize(q.voxelCount());
    const glm::ivec3 c = q.dims;
    std::vector<int> xs(size_t(c.x)), ys(size_t(c.y));
    for (int i = 0; i < c.x; ++i) xs[size_t(i)] = nearestFull(i, g.dims.x, c.x);
    for (int j = 0; j < c.y; ++j) ys[size_t(j)] = nearestFull(j, g.dims.y, c.y);
    // The rows are evenly spaced but for the clamp at the far end: read from the first at a
    // step of F, the last row picked alone when the clamp moved it.
    parallelFor(size_t(c.z), [&](size_t k) {
      const int z = nearestFull(int(k), g.dims.z, c.z);
      std::vector<int16_t> rows(size_t(g.dims.x) * size_t(c.y));
      int even = c.y;
      while (even > 1 && ys[size_t(even - 1)] != ys[0] + (even - 1) * f) --even;
      reader_.readRows(z, ys[0], f, even, rows.data());
      for (int j = even; j < c.y; ++j)
        reader_.readRows(z, ys[size_t(j)], 1, 1, rows.data() + size_t(j) * size_t(g.dims.x));
      int16_t* out = q.voxels.data() + k * size_t(c.x) * size_t(c.y);
      for (int j = 0; j < c.y; ++j)
        for (int i = 0; i < c.x; ++i)
          out[size_t(j) * size_t(c.x) + size_t(i)] =
              rows[size_t(j) * size_t(g.dims.x) + size_t(xs[size_t(i)])];
    });
    return q;
  }

  RawSliceReader reader_;
  std::string input_;
  std::optional<Volume> quick_;
  std::optional<ValueRange> range_;
  CoarseThread pass_;  // last: stopped and joined before the members it reads go
};

class VolumeSource : public SlabSource {
 public:
  VolumeSource(const Volume& v, int factor) : v_(v), factor_(factor), geometry_(withoutVoxels(v)) {
    if (v.voxelCount() == 0 || v.voxels.size() != v.voxelCount())
      throw inputError("the volume is empty or its voxel count does not match its dimensions");
  }
  const Volume& geometry() const override { return geometry_; }
  void readSlices(int first, int end, int16_t* dest) override {
    const size_t slice = size_t(v_.dims.x) * size_t(v_.dims.y);
    std::memcpy(dest, v_.voxels.data() + size_t(first) * slice,
                size_t(end - first) * slice * sizeof(int16_t));
  }
  const int16_t* slicesInPlace(int first) const override {
    return v_.voxels.data() + size_t(first) * size_t(v_.dims.x) * size_t(v_.dims.y);
  }
  const Volume* whole() const override { return &v_; }
  const Volume& coarse() override {
    if (!coarse_) coarse_ = coarseLevel(v_, factor_);
    return *coarse_;
  }
  std::string describe() const override { return "in memory"; }

 private:
  const Volume& v_;
  int factor_;
  Volume geometry_;
  std::optional<Volume> coarse_;
};

#ifdef VOXRAY_HAS_ZARR
class ZarrSource : public SlabSource {
 public:
  explicit ZarrSource(const std::string& path)
      : store_(zarrFolderStore(path)), level0_(*store_, 0), path_(path) {}
  const Volume& geometry() const override { return level0_.geometry(); }
  void readSlices(int first, int end, int16_t* dest) override {
    level0_.readSlices(first, end, dest);
  }
  int preferredSlices() const override { return level0_.chunkSlices(); }
  std::optional<ValueRange> statedRange() const override { return level0_.statedRange(); }
  size_t missingChunks() const override { return level0_.missingChunks(); }
  // The first level after the coarse one with at most kQuickVoxels (the 8 GiB CT: level 4, 2
  // MiB, against level 3's 16 MiB): read and marched in a fraction of the coarse level's time.
  const Volume* quickLevel() override {
    if (quickChecked_) return quick_ ? &*quick_ : nullptr;
    quickChecked_ = true;
    const int pick = coarsePick();
    for (int l = pick + 1; pick > 0 && l < level0_.levelCount(); ++l) {
      OmeZarrLevel level(*store_, l);
      if (level.geometry().voxelCount() <= kQuickVoxels) {
        quick_ = readLevel(level);
        break;
      }
    }
    return quick_ ? &*quick_ : nullptr;
  }
  glm::ivec3 coarseDims() override {
    const int pick = coarsePick();
    if (pick == 0) return (level0_.geometry().dims + 3) / 4;
    return OmeZarrLevel(*store_, pick).geometry().dims;
  }
  void startCoarse() override {
    if (!quick_) return;
    // Its own level reader on the store (a folder: files read, nothing shared but the path).
    pass_.start([this, pick = coarsePick()](const std::atomic<bool>&) {
      OmeZarrLevel level(*store_, pick);
      return readLevel(level);
    });
  }
  bool coarseReady() const override { return coarse_ || !quick_ || pass_.done(); }
  const Volume& coarse() override {
    if (coarse_) return *coarse_;
    const Volume& g = level0_.geometry();
    const int pick = coarsePick();
    if (quick_) {
      startCoarse();
      coarse_ = std::move(pass_.get());
    } else if (pick > 0) {
      OmeZarrLevel level(*store_, pick);
      coarse_ = readLevel(level);
    } else {
      coarse_ = streamedMean(level0_.geometry(), 4, [&](int a, int b, int16_t* d) {
        level0_.readSlices(a, b, d);
      });  // one level: its 4x mean, 4 slices at a time
      coarse_->slope = g.slope;
      coarse_->intercept = g.intercept;
    }
    return *coarse_;
  }
  std::string describe() const override { return "OME-Zarr " + path_ + " level 0, streamed"; }

 private:
  // The first level with at most 1/64 of the voxels (a 4x mean along each axis) and at most
  // kCoarseBytes, else the coarsest; 0 when there is one level. The cap: every preview marches
  // it; the 8 GiB CT's 4x level (128 MiB) took 1.9 s to open and 3.4 s a 512x512 preview on the
  // shared 2-core Xeon (run E in docs/bench/out-of-core-pocl.txt). Metadata only.
  int coarsePick() {
    if (pick_ >= 0) return pick_;
    constexpr size_t kCoarseBytes = size_t(32) << 20;
    const Volume& g = level0_.geometry();
    int pick = level0_.levelCount() - 1;
    for (int l = 1; l < level0_.levelCount(); ++l) {
      OmeZarrLevel level(*store_, l);
      const size_t n = level.geometry().voxelCount();
      if (n * 64 <= g.voxelCount() && n * sizeof(int16_t) <= kCoarseBytes) {
        pick = l;
        break;
      }
    }
    pick_ = pick;
    return pick;
  }
  // LEVEL whole, with level 0's value mapping.
  Volume readLevel(OmeZarrLevel& level) const {
    Volume c = level.geometry();
    c.voxels.resize(c.voxelCount());
    level.readSlices(0, c.dims.z, c.voxels.data());
    c.slope = level0_.geometry().slope;
    c.intercept = level0_.geometry().intercept;
    return c;
  }

  std::unique_ptr<ZarrStore> store_;
  OmeZarrLevel level0_;
  std::string path_;
  int pick_ = -1;
  bool quickChecked_ = false;
  std::optional<Volume> quick_, coarse_;
  CoarseThread pass_;  // last: stopped and joined before the members it reads go
};
#endif

}  // namespace

std::unique_ptr<SlabSource> rawSlabSource(const std::string& input, const RawLayout& layout) {
  return std::make_unique<RawSource>(input, layout);
}

std::unique_ptr<SlabSource> volumeSlabSource(const Volume& volume, int coarseFactor) {
  return std::make_unique<VolumeSource>(volume, coarseFactor);
}

#ifdef VOXRAY_HAS_ZARR
std::unique_ptr<SlabSource> omeZarrSlabSource(const std::string& path) {
  return std::make_unique<ZarrSource>(path);
}
#endif

}  // namespace voxray
