#include "part_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "voxray/io/error.h"

namespace voxray::pacs {
namespace {

// CONTENT into a new file PATH. Plain POSIX calls: one write for the whole file.
void writeFile(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  int error = fd < 0 ? errno : 0;
  for (size_t done = 0; !error && done < content.size();) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) error = n < 0 ? errno : ENOSPC;
    if (n > 0) done += size_t(n);
  }
  if (fd >= 0 && ::close(fd) != 0 && !error) error = errno;
  if (error)
    throw outputError("cannot write " + path + " (" + std::strerror(error) +
                      "): the disk may be full; free space");
}

}  // namespace

PartWriter::PartWriter(Written written)
    : written_(std::move(written)), thread_([this] { work(); }) {}

PartWriter::~PartWriter() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void PartWriter::rethrow() {
  if (error_) std::rethrow_exception(error_);
}

void PartWriter::add(std::string path, std::shared_ptr<std::string> content) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || queuedBytes_ <= kMaxQueuedBytes; });
  rethrow();
  queuedBytes_ += content->size();
  queue_.emplace_back(std::move(path), std::move(content));
  lock.unlock();
  changed_.notify_all();
}

void PartWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || (queue_.empty() && !busy_); });
  rethrow();
}

void PartWriter::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stop_ || !queue_.empty(); });
    if (stop_ || error_) return;
    auto [path, content] = std::move(queue_.front());
    queue_.pop_front();
    queuedBytes_ -= content->size();
    busy_ = true;
    lock.unlock();
    std::exception_ptr error;
    try {
      writeFile(path, *content);
      // The only holder left (an import drops its share, never takes one): moved out.
      if (written_)
        written_(path, content.use_count() == 1 ? std::move(*content) : std::string(*content));
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    busy_ = false;
    if (error) error_ = error;
    changed_.notify_all();
    if (error_) return;
  }
}

}  // namespace voxray::pacs
