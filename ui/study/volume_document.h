#pragma once
// The volume on screen, shared read-only by the slice views and the render thread, and
// the one that was on screen before (restored when a new one cannot be shown). A 4D input
// is a series of volumes, one per time point, of which one is on screen: switching the time
// point (setTimePoint) swaps the volume without opening a new study, and tells timeChanged,
// not changed, so that views keep their zoom, measurements and camera.
#include <memory>
#include <string>

#include "no_qt.h"
#include "notifier.h"
#include "time_series.h"
#include "voxray/io/volume.h"

namespace voxray {

class VolumeDocument {
 public:
  const std::shared_ptr<const Volume>& volume() const { return volume_; }
  const std::string& name() const { return name_; }  // what the title bar shows
  bool empty() const { return !volume_; }
  double minSpacingMm() const;

  void set(std::shared_ptr<const Volume> volume, std::string name);
  // A series (non-empty; its volumes share one geometry, as loadVolumeSeries gives them)
  // with time point TIMEPOINT (clamped into range) on screen.
  void setSeries(VolumeSeries series, std::string name, int timePoint = 0);
  // Goes back to the volume shown before the last set() (after a failed upload).
  void restorePrevious();

  const VolumeSeries& series() const { return series_; }
  int timePoint() const { return timePoint_; }
  int timePoints() const { return int(series_.size()); }
  // Shows time point T; false (and nothing changes) when it is out of range or already shown.
  bool setTimePoint(int t);

  Notifier<> changed;      // another study (volume or series)
  Notifier<> timeChanged;  // another time point of the same series

 private:
  std::shared_ptr<const Volume> volume_;
  VolumeSeries series_, previousSeries_;
  int timePoint_ = 0, previousTimePoint_ = 0;
  std::string name_, previousName_;
};

}  // namespace voxray
