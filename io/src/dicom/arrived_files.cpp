#include "arrived_files.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include <sys/mman.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <new>

#include "pixel_decode.h"
#include "voxray/io/error.h"
#include "voxray/io/raw_import.h"

namespace voxray::dicom {
namespace {

constexpr size_t kReservedSlices = 1024;

}  // namespace

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

void ArrivedFiles::add(const std::string& path, std::shared_ptr<const std::string> bytes) {
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

VoxelVector ArrivedFiles::release() {
  VoxelVector out = std::move(voxels_);
  voxels_ = {};
  files_.clear();
  slots_.clear();
  sliceSize_ = 0;
  populated_ = 0;
  return out;
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
    // How many files are coming is not known (WADO-RS does not say). Growing by doubling
    // cost 0.1 s of CPU for 400 CT slices (copies, and page faults on each new buffer), so
    // address space for kReservedSlices is taken at once: only the pages written are
    // memory. Past it (or where that much address space is refused) the buffer doubles.
    size_t want = std::max(voxels_.capacity() * 2, kReservedSlices * sliceSize_);
    want = std::min(want, std::max(kMaxVoxels, needed));
    try {
      voxels_.reserve(want);
    } catch (const std::bad_alloc&) {
      voxels_.reserve(std::max(voxels_.capacity() * 2, needed));
    }
    populated_ = voxels_.size();
  }
#ifdef MADV_POPULATE_WRITE
  if (needed > populated_) {
    // Page tables for the next slices in one call (4 KiB page faults one by one cost a
    // tenth of the worker's CPU time); ignored by kernels before Linux 5.14.
    const size_t ahead = std::min(voxels_.capacity(), needed + 16 * sliceSize_);
    auto* begin = reinterpret_cast<char*>(voxels_.data() + populated_);
    const uintptr_t page = 4096;
    auto from = (reinterpret_cast<uintptr_t>(begin) + page - 1) & ~(page - 1);
    auto to = reinterpret_cast<uintptr_t>(voxels_.data() + ahead) & ~(page - 1);
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
    populated_ = ahead;
  }
#endif
  voxels_.resize(needed);
  slots_.emplace_back();
  return k;
}

void ArrivedFiles::process(const std::string& path, std::shared_ptr<const std::string> bytes) {
  auto parsed = std::make_unique<DcmFileFormat>();
  File file;
  std::string why;
  try {
    // The pixel data stays in BYTES (PARSED keeps them): uncompressed 16-bit frames are
    // copied from there into their slots as the folder import reads them from files
    // (NativeFrames); the others are decoded by PixelFile, made when first needed.
    if (readFrameHeaders(path, std::move(bytes), *parsed, file.frames, why) != ScanResult::Image)
      return;
    NativeFrames native(*parsed);
    std::unique_ptr<PixelFile> pixels;
    std::vector<int32_t> values;
    for (const FrameHeader& h : file.frames) {
      const size_t n = size_t(h.columns) * size_t(h.rows);
      const bool direct = native.fits(h);
      if (!direct) {
        if (!pixels) pixels = std::make_unique<PixelFile>(path, std::move(parsed));
        pixels->frameValues(h, values);
        if (values.size() != n) return;  // the import says what is wrong with it
      }
      if (sliceSize_ == 0) sliceSize_ = n;
      if (n != sliceSize_) return;  // not one stack with the first file
      const size_t k = newSlot();
      Slot& slot = slots_[k];
      slot.air = airValue(h.modality);
      auto* words = reinterpret_cast<uint16_t*>(voxels_.data() + k * sliceSize_);
      if (direct && native.read(h, words))
        slot.scale = storeWords(words, n, h, slot.air);
      else if (direct)
        return;  // a slot the import does not use: it then reads the files from disk
      else
        slot.scale = storeSlice(values, h, slot.air, voxels_.data() + k * sliceSize_);
      file.slots.push_back(k);
    }
  } catch (const std::exception&) {
    return;  // Error or bad_alloc: the import reads the file again and reports it
  }
  files_[pathKey(path)] = std::move(file);
}

}  // namespace voxray::dicom
