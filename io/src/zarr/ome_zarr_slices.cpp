// One level of an OME-Zarr as a SliceSource (voxray-cli convert reading a pyramid a chunk row
// at a time, issue 38): OmeZarrLevel over a store the source owns.
#include <sstream>

#include "ome_zarr_meta.h"
#include "voxray/io/ome_zarr.h"
#include "zarr_array.h"

namespace voxray {
namespace {

class ZarrSlices : public SliceSource {
 public:
  ZarrSlices(std::unique_ptr<ZarrStore> store, int level, zarr::ArrayMeta meta)
      : store_(std::move(store)), level_(*store_, level), meta_(std::move(meta)) {}
  const Volume& geometry() const override { return level_.geometry(); }
  void readSlices(int first, int end, int16_t* dest) override {
    level_.readSlices(first, end, dest);
  }
  std::vector<std::string> warnings() const override {
    std::vector<std::string> w = level_.geometry().warnings;
    if (level_.missingChunks() == 0) return w;
    // As importOmeZarr says it of a whole read: of the chunks of the three spatial axes.
    uint64_t total = 1;
    const size_t n = meta_.shape.size();
    for (size_t a = n - 3; a < n; ++a)
      total *= (meta_.shape[a] + meta_.chunks[a] - 1) / meta_.chunks[a];
    std::ostringstream fill;
    fill << meta_.fill;
    w.push_back(std::to_string(level_.missingChunks()) + " of " + std::to_string(total) +
                " chunks are missing in " + store_->where(meta_.path) +
                "; they show the fill value " + fill.str());
    return w;
  }

 private:
  std::unique_ptr<ZarrStore> store_;
  OmeZarrLevel level_;
  zarr::ArrayMeta meta_;
};

}  // namespace

std::unique_ptr<SliceSource> omeZarrSliceSource(std::unique_ptr<ZarrStore> store, int level) {
  const zarr::Pyramid pyramid = zarr::readPyramid(*store);
  zarr::checkLevelIndex(pyramid, level, store->where(""));
  zarr::ArrayMeta m =
      zarr::readArrayMeta(*store, pyramid.levels[size_t(level)].path, pyramid.format);
  using K = detail::SampleKind;
  if (m.kind != K::I16 && m.kind != K::U8 && m.kind != K::I8) return nullptr;
  return std::make_unique<ZarrSlices>(std::move(store), level, std::move(m));
}

}  // namespace voxray
