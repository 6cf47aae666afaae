#include "background_task.h"

namespace voxray {

BackgroundTask::~BackgroundTask() {
  cancel();
  wait();
}

void BackgroundTask::start(std::function<void()> job) {
  wait();
  cancel_ = false;
  thread_ = std::thread(std::move(job));
}

void BackgroundTask::wait() {
  if (thread_.joinable()) thread_.join();
}

void BackgroundTask::post(Event event) const {
  if (post_)
    post_(std::move(event));
  else
    event();
}

}  // namespace voxray
