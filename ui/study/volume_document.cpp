#include "volume_document.h"

#include <algorithm>

namespace voxray {

double VolumeDocument::minSpacingMm() const {
  if (!volume_) return 1.0;
  const auto& s = volume_->spacingMm;
  return std::min({s.x, s.y, s.z});
}

void VolumeDocument::set(std::shared_ptr<const Volume> volume, std::string name) {
  previous_ = std::move(volume_);
  previousName_ = std::move(name_);
  volume_ = std::move(volume);
  name_ = std::move(name);
  changed.notify();
}

void VolumeDocument::restorePrevious() {
  if (!previous_) return;
  volume_ = std::move(previous_);
  name_ = std::move(previousName_);
  previous_.reset();
  changed.notify();
}

}  // namespace voxray
