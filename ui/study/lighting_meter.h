#pragma once
// The Light group's "Measure on this view", Qt-free: runs a LightingMeasureTask on the
// document's volume and puts its results into LightingFigures; a new volume cancels it (its
// late result is dropped) and clears the figures seen on the old one.
#include <string>

#include "lighting_figures.h"
#include "lighting_measure.h"
#include "no_qt.h"
#include "volume_document.h"

namespace voxray {

class LightingMeter {
 public:
  // POST: where results arrive (the GUI thread; none: the measuring thread, for tests).
  LightingMeter(VolumeDocument& doc, LightingFigures& figures, BackgroundTask::Post post = {});
  ~LightingMeter();
  LightingMeter(const LightingMeter&) = delete;
  LightingMeter& operator=(const LightingMeter&) = delete;

  // Measures VIEW (the frame on screen) on DEVICE (a ClContext selector). Nothing without a
  // volume. Returns whether it started.
  bool measure(const RenderParams& view, const std::string& device,
               const LightingMeasureOptions& o = {});
  bool running() const { return task_ && task_->running(); }
  void wait();
  const std::string& lastError() const { return lastError_; }  // "" after a success

 private:
  VolumeDocument& doc_;
  LightingFigures& figures_;
  BackgroundTask::Post post_;
  std::string device_, lastError_;
  int docConnection_ = 0;
  std::unique_ptr<LightingMeasureTask> task_;  // per device
};

}  // namespace voxray
