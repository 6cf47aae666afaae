#include "volume_document.h"

#include <algorithm>

namespace voxray {

double VolumeDocument::minSpacingMm() const {
  if (!volume_) return 1.0;
  const auto& s = volume_->spacingMm;
  return std::min({s.x, s.y, s.z});
}

void VolumeDocument::set(std::shared_ptr<const Volume> volume, std::string name) {
  VolumeSeries one;
  if (volume) one.push_back(std::move(volume));
  setSeries(std::move(one), std::move(name), 0);
}

void VolumeDocument::setSeries(VolumeSeries series, std::string name, int timePoint) {
  previousSeries_ = std::move(series_);
  previousTimePoint_ = timePoint_;
  previousName_ = std::move(name_);
  series_ = std::move(series);
  timePoint_ = series_.empty() ? 0 : std::clamp(timePoint, 0, int(series_.size()) - 1);
  volume_ = series_.empty() ? nullptr : series_[size_t(timePoint_)];
  name_ = std::move(name);
  changed.notify();
}

void VolumeDocument::restorePrevious() {
  if (previousSeries_.empty()) return;
  series_ = std::move(previousSeries_);
  timePoint_ = previousTimePoint_;
  volume_ = series_[size_t(timePoint_)];
  name_ = std::move(previousName_);
  previousSeries_.clear();
  changed.notify();
}

bool VolumeDocument::setTimePoint(int t) {
  if (t < 0 || t >= int(series_.size()) || t == timePoint_) return false;
  timePoint_ = t;
  volume_ = series_[size_t(t)];
  timeChanged.notify();
  return true;
}

}  // namespace voxray
