#pragma once
// The one way the UI runs work off its thread (a load, a series scan, the render loop): a job
// on a thread of its own, a cancel flag the job polls or hands to io (LoadOptions::cancel),
// and events that reach the owner through its Post. The workstation posts to the GUI thread
// (postTo in ui/widgets/gui_post.h), so progress, results and errors are handled where the
// widgets live; without a Post (the model tests) events run on the worker thread.
#include <atomic>
#include <functional>
#include <thread>

#include "no_qt.h"

namespace voxray {

class BackgroundTask {
 public:
  using Event = std::function<void()>;
  using Post = std::function<void(Event)>;

  explicit BackgroundTask(Post post = {}) : post_(std::move(post)) {}
  ~BackgroundTask();  // cancels and waits: a job never outlives its owner
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;

  // Runs JOB on a new thread with the cancel flag cleared; waits for a previous job first.
  void start(std::function<void()> job);
  // Asks the job to stop. A job blocked on a condition variable must also be woken.
  void cancel() { cancel_ = true; }
  bool cancelled() const { return cancel_; }
  const std::atomic<bool>* cancelFlag() const { return &cancel_; }
  // Waits for the job to return (at once if none runs).
  void wait();
  // Sends EVENT to the owner: through the Post, or at once on the calling thread. An event
  // must capture what it needs by value: it may run after the job (not the owner) is gone.
  void post(Event event) const;

 private:
  Post post_;
  std::atomic<bool> cancel_{false};
  std::thread thread_;
};

}  // namespace voxray
