#pragma once
// Files handed over while they are still arriving (a PACS retrieval): one worker thread reads
// each file's headers and decodes its frames from the bytes in memory as it comes, so that
// when the last file is in only the assembly is left. The results are a cache for the
// import: a file the worker could not read or decode completely is not in it, and the import
// reads that file from disk as it reads any other (the same results and the same errors).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "frame_header.h"
#include "value_mapping.h"
#include "voxray/io/voxel_memory.h"

namespace voxray::dicom {

// The key files are found by: PATH in lexically normal form.
std::string pathKey(const std::string& path);

class ArrivedFiles {
 public:
  ArrivedFiles() = default;
  ~ArrivedFiles();  // stops the worker; files not processed yet are dropped
  ArrivedFiles(const ArrivedFiles&) = delete;
  ArrivedFiles& operator=(const ArrivedFiles&) = delete;

  // BYTES: the whole file that is (or will be) at PATH; shared, not copied (the PACS cache
  // writes the same bytes to its file meanwhile).
  void add(const std::string& path, std::shared_ptr<const std::string> bytes);
  // Waits until every file added so far is processed, or until *CANCEL is true.
  void drain(const std::atomic<bool>* cancel);

  // The decoded frames below are read only after drain().
  struct File {
    std::vector<FrameHeader> frames;
    std::vector<size_t> slots;  // frame f's values are slice slots[f] of voxels()
  };
  // The file at PATH when every one of its frames was decoded, else nullptr.
  const File* find(const std::string& path) const;
  struct Slot {
    SliceScale scale;
    double air = 0.0;  // the padding value storeSlice was given
  };
  const std::vector<Slot>& slots() const { return slots_; }
  size_t sliceSize() const { return sliceSize_; }
  // Slice k at k * sliceSize(), in the order the files arrived.
  VoxelVector& voxels() { return voxels_; }
  // Hands the slices over (reordered by the caller) and forgets every file: what is asked
  // afterwards is read from disk.
  VoxelVector release();

 private:
  void work();
  void process(const std::string& path, std::shared_ptr<const std::string> bytes);
  // A slot of sliceSize_ voxels at the end of voxels_; its index.
  size_t newSlot();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<std::string, std::shared_ptr<const std::string>>> queue_;
  bool busy_ = false, stop_ = false;
  std::thread worker_;

  std::map<std::string, File> files_;  // by pathKey
  std::vector<Slot> slots_;
  VoxelVector voxels_;
  size_t sliceSize_ = 0;
  size_t populated_ = 0;  // voxels_ elements with page tables
};

}  // namespace voxray::dicom
