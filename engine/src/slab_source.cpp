#include "voxray/engine/slab_source.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <optional>
#include <vector>

#include "voxray/engine/coarse_level.h"
#include "voxray/io/error.h"
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
                    ValueRange* range = nullptr) {
  Volume slab = g;
  Volume c;
  int lo = INT16_MAX, hi = INT16_MIN;
  for (int z0 = 0; z0 < g.dims.z; z0 += factor) {
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

// A raw file or slice stack read with pread a range of slices at a time (RawSliceReader); its
// coarse level the 4x box mean made in one streamed pass, which also finds the value range.
class RawSource : public SlabSource {
 public:
  RawSource(const std::string& input, const RawLayout& layout)
      : reader_(input, layout), input_(input) {}
  const Volume& geometry() const override { return reader_.geometry(); }
  void readSlices(int first, int end, int16_t* dest) override {
    reader_.readSlices(first, end, dest);
  }
  int preferredSlices() const override { return 0; }
  std::optional<ValueRange> statedRange() const override { return range_; }
  const Volume& coarse() override {
    if (!coarse_) {
      ValueRange r;
      coarse_ = streamedMean(
          reader_.geometry(), 4, [&](int a, int b, int16_t* d) { reader_.readSlices(a, b, d); },
          &r);
      range_ = r;
    }
    return *coarse_;
  }
  std::string describe() const override { return "raw " + input_ + ", read on demand"; }

 private:
  RawSliceReader reader_;
  std::string input_;
  std::optional<Volume> coarse_;
  std::optional<ValueRange> range_;
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
  const Volume& coarse() override {
    if (coarse_) return *coarse_;
    const Volume& g = level0_.geometry();
    // The first level with at most 1/64 of the voxels (a 4x mean along each axis) and at most
    // kCoarseBytes, else the coarsest: opening then reads that level alone. The cap: the first
    // image waits for it and every preview marches it; the 8 GiB CT's 4x level (128 MiB) took
    // 1.9 s to open and 3.4 s a 512x512 preview on the shared 2-core Xeon (run E in
    // docs/bench/out-of-core-pocl.txt), against the 2 s to the first image.
    constexpr size_t kCoarseBytes = size_t(32) << 20;
    int pick = level0_.levelCount() - 1;
    for (int l = 1; l < level0_.levelCount(); ++l) {
      OmeZarrLevel level(*store_, l);
      const size_t n = level.geometry().voxelCount();
      if (n * 64 <= g.voxelCount() && n * sizeof(int16_t) <= kCoarseBytes) {
        pick = l;
        break;
      }
    }
    if (pick > 0) {
      OmeZarrLevel level(*store_, pick);
      Volume c = level.geometry();
      c.voxels.resize(c.voxelCount());
      level.readSlices(0, c.dims.z, c.voxels.data());
      coarse_ = std::move(c);
    } else {
      coarse_ = streamedMean(level0_.geometry(), 4, [&](int a, int b, int16_t* d) {
        level0_.readSlices(a, b, d);
      });  // one level: its 4x mean, 4 slices at a time
    }
    coarse_->slope = g.slope;
    coarse_->intercept = g.intercept;
    return *coarse_;
  }
  std::string describe() const override { return "OME-Zarr " + path_ + " level 0, streamed"; }

 private:
  std::unique_ptr<ZarrStore> store_;
  OmeZarrLevel level0_;
  std::string path_;
  std::optional<Volume> coarse_;
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
