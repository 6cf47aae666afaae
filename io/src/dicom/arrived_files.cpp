#include "arrived_files.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include <chrono>
#include <filesystem>

#include "pixel_decode.h"
#include "voxray/io/error.h"

namespace voxray::dicom {

std::string pathKey(const std::string& path) {
  return std::filesystem::path(path).lexically_normal().string();
}

ArrivedFiles::~ArrivedFiles() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void ArrivedFiles::add(const std::string& path, std::string bytes) {
  {
    std::lock_guard lock(mutex_);
    queue_.emplace_back(path, std::move(bytes));
    if (!worker_.joinable()) worker_ = std::thread([this] { work(); });
  }
  changed_.notify_all();
}

void ArrivedFiles::drain(const std::atomic<bool>* cancel) {
  std::unique_lock lock(mutex_);
  // Cancel is a flag, not an event: looked at every 50 ms.
  while (!queue_.empty() || busy_) {
    if (cancel && *cancel) return;
    changed_.wait_for(lock, std::chrono::milliseconds(50));
  }
}

const ArrivedFiles::File* ArrivedFiles::find(const std::string& path) const {
  auto it = files_.find(pathKey(path));
  return it == files_.end() ? nullptr : &it->second;
}

void ArrivedFiles::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    auto [path, bytes] = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    process(path, std::move(bytes));
    lock.lock();
    busy_ = false;
    changed_.notify_all();
  }
}

size_t ArrivedFiles::newSlot() {
  const size_t k = slots_.size();
  const size_t needed = (k + 1) * sliceSize_;
  if (needed > voxels_.capacity()) {
    // Doubling: the copies add up to less than the final size, and happen while the
    // transfer still runs.
    constexpr size_t kFirstSlices = 64;
    voxels_.reserve(std::max(voxels_.capacity() * 2, kFirstSlices * sliceSize_));
  }
  voxels_.resize(needed);
  slots_.emplace_back();
  return k;
}

void ArrivedFiles::process(const std::string& path, std::string bytes) {
  auto parsed = std::make_unique<DcmFileFormat>();
  File file;
  std::string why;
  try {
    if (readFrameHeaders(path, bytes, *parsed, file.frames, why) != ScanResult::Image) return;
    bytes = std::string();  // DCMTK holds its own copy of every value
    PixelFile pixels(path, std::move(parsed));
    std::vector<int32_t> values;
    for (const FrameHeader& h : file.frames) {
      pixels.frameValues(h, values);
      const size_t n = size_t(h.columns) * size_t(h.rows);
      if (values.size() != n) return;  // the import says what is wrong with it
      if (sliceSize_ == 0) sliceSize_ = n;
      if (n != sliceSize_) return;  // not one stack with the first file
      const size_t k = newSlot();
      slots_[k].air = airValue(h.modality);
      slots_[k].scale = storeSlice(values, h, slots_[k].air, voxels_.data() + k * sliceSize_);
      file.slots.push_back(k);
    }
  } catch (const std::exception&) {
    return;  // Error or bad_alloc: the import reads the file again and reports it
  }
  files_[pathKey(path)] = std::move(file);
}

}  // namespace voxray::dicom
