#pragma once
// Which time point a second series shows (issue 36): the fusion overlay over the study, the
// prior beside it in compare. The rule: when the study and the second series are both 4D
// with the same number of time points, the second follows the study's time slider at the
// same index (the phases or frames of one protocol line up); otherwise (either is 3D, or the
// counts differ) it shows a time point of its own, chosen by the user in the fusion panel or
// the compare bar, time point 0 until then. Qt-free.
#include "no_qt.h"
#include "volume_document.h"

namespace voxray {

class TimeFollow {
 public:
  // The second series' time points (1 for a 3D one); its own choice is clamped into range.
  void setCount(int count);
  int count() const { return count_; }
  // The study's time point and count (its time slider).
  void setMain(int point, int count);
  bool follows() const { return count_ > 1 && count_ == mainCount_; }
  // The user's choice, used while it does not follow; clamped into range.
  void setOwn(int point);
  int own() const { return own_; }
  // The time point to show.
  int shown() const;

 private:
  int count_ = 1, mainCount_ = 1, mainPoint_ = 0, own_ = 0;
};

// The compare prior: SECOND (its series) shows FOLLOW's time point for MAIN's time slider.
void showFollowedTime(VolumeDocument& second, TimeFollow& follow, const VolumeDocument& main);

}  // namespace voxray
