#include "time_follow.h"

#include <algorithm>

namespace voxray {

void TimeFollow::setCount(int count) {
  count_ = std::max(1, count);
  own_ = std::clamp(own_, 0, count_ - 1);
}

void TimeFollow::setMain(int point, int count) {
  mainCount_ = std::max(1, count);
  mainPoint_ = std::clamp(point, 0, mainCount_ - 1);
}

void TimeFollow::setOwn(int point) { own_ = std::clamp(point, 0, count_ - 1); }

int TimeFollow::shown() const { return follows() ? mainPoint_ : own_; }

void showFollowedTime(VolumeDocument& second, TimeFollow& follow, const VolumeDocument& main) {
  follow.setCount(second.timePoints());
  follow.setMain(main.timePoint(), main.timePoints());
  second.setTimePoint(follow.shown());  // unchanged: nothing told
}

}  // namespace voxray
