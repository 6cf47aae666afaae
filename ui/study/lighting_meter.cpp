#include "lighting_meter.h"

namespace voxray {

LightingMeter::LightingMeter(VolumeDocument& doc, LightingFigures& figures,
                             BackgroundTask::Post post)
    : doc_(doc), figures_(figures), post_(std::move(post)) {
  docConnection_ = doc_.changed.connect([this] {
    if (task_) task_->cancel();
    figures_.clear();
  });
}

LightingMeter::~LightingMeter() {
  doc_.changed.disconnect(docConnection_);
  task_.reset();  // cancels and waits before the figures can go
}

bool LightingMeter::measure(const RenderParams& view, const std::string& device,
                            const LightingMeasureOptions& o) {
  if (doc_.empty()) return false;
  if (!task_ || device != device_) {
    task_.reset();
    device_ = device;
    LightingMeasureTask::Callbacks cb;
    cb.done = [this](std::vector<LightingMeasurement> m) {
      lastError_.clear();
      figures_.setMeasured(m);
    };
    cb.failed = [this](const std::string& message) {
      lastError_ = message;
      figures_.setMeasuring(false);
    };
    task_ = std::make_unique<LightingMeasureTask>(device_, cb, post_);
  }
  figures_.setMeasuring(true);
  task_->start(doc_.volume(), view, o);
  return true;
}

void LightingMeter::wait() {
  if (task_) task_->wait();
}

}  // namespace voxray
