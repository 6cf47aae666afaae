#pragma once
// The files of a WADO-RS retrieval written on a thread of their own, in the order the parts
// arrived, so that receiving never waits for the file system: the transfer's thread only
// reads the socket and splits the body (issue 39 item 8). Creating the 400 files of a CT
// series took ~0.1 s of CPU on the receiving thread (ext4 without a journal skips the
// inodes deleted in the last minute, one by one), while the server waited for us to read.
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace voxray::pacs {

class PartWriter {
 public:
  // WRITTEN (may be empty) gets each file once it is on disk, with its content (moved out
  // when no one else holds it, else copied), on the writer's thread.
  using Written = std::function<void(const std::string& path, std::string content)>;
  explicit PartWriter(Written written);
  ~PartWriter();  // stops: what is not written yet is dropped
  PartWriter(const PartWriter&) = delete;
  PartWriter& operator=(const PartWriter&) = delete;

  // Queues CONTENT for PATH; waits while more than kMaxQueuedBytes are queued. Throws the
  // error that stopped the writer, if one did.
  void add(std::string path, std::shared_ptr<std::string> content);
  // Waits until everything queued is written; throws the writer's error, if any.
  void finish();

  // The most bytes queued before add() waits: the writer falls behind only when the disk
  // is slower than the network; the import holds every image in memory meanwhile anyway.
  static constexpr size_t kMaxQueuedBytes = size_t(256) << 20;

 private:
  void work();
  void rethrow();  // under mutex_

  Written written_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<std::string, std::shared_ptr<std::string>>> queue_;
  size_t queuedBytes_ = 0;
  bool busy_ = false, stop_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace voxray::pacs
