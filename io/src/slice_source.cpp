#include "voxray/io/slice_source.h"

#include <cstring>

#include "voxray/io/error.h"

namespace voxray {
namespace {

class VolumeSlices : public SliceSource {
 public:
  explicit VolumeSlices(const Volume& v) : v_(v) {
    geometry_.dims = v.dims;
    geometry_.spacingMm = v.spacingMm;
    geometry_.originMm = v.originMm;
    geometry_.direction = v.direction;
    geometry_.slope = v.slope;
    geometry_.intercept = v.intercept;
    geometry_.unit = v.unit;
    geometry_.modality = v.modality;
    geometry_.window = v.window;
    geometry_.suv = v.suv;
    geometry_.timePoint = v.timePoint;
    geometry_.timePoints = v.timePoints;
    geometry_.sourceType = v.sourceType;
    geometry_.warnings = v.warnings;
    if (v.voxels.size() != v.voxelCount())
      throw inputError("the volume's voxel count does not match its dimensions");
  }
  const Volume& geometry() const override { return geometry_; }
  void readSlices(int first, int end, int16_t* dest) override {
    const size_t slice = size_t(v_.dims.x) * size_t(v_.dims.y);
    std::memcpy(dest, slicesInPlace(first), size_t(end - first) * slice * sizeof(int16_t));
  }
  const int16_t* slicesInPlace(int first) const override {
    return v_.voxels.data() + size_t(first) * size_t(v_.dims.x) * size_t(v_.dims.y);
  }
  std::optional<ValueRange> storedRange() const override { return voxray::storedRange(v_); }

 private:
  const Volume& v_;
  Volume geometry_;  // without voxels (no study identity: writers have no use for it)
};

class RawSlices : public SliceSource {
 public:
  RawSlices(const std::string& input, const RawLayout& layout) : reader_(input, layout) {}
  const Volume& geometry() const override { return reader_.geometry(); }
  void readSlices(int first, int end, int16_t* dest) override {
    reader_.readSlices(first, end, dest);
  }
  std::optional<ValueRange> storedRange() const override { return reader_.storedRange(); }

 private:
  RawSliceReader reader_;
};

}  // namespace

std::unique_ptr<SliceSource> volumeSliceSource(const Volume& volume) {
  return std::make_unique<VolumeSlices>(volume);
}

std::unique_ptr<SliceSource> rawSliceSource(const std::string& input, const RawLayout& layout) {
  return std::make_unique<RawSlices>(input, layout);
}

}  // namespace voxray
