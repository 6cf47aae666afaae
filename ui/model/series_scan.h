#pragma once
// The series picker's background work: list the series of a DICOM input (headers only),
// then make a thumbnail of each candidate's middle slice, one candidate at a time, on a
// thread of its own so the dialog stays responsive. Thumbnails load the candidate through
// importDicom (the only decoder io offers), so candidates above a voxel budget get none.
// Events arrive on the worker thread; the receiver hops to its own thread.
#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include "no_qt.h"
#include "voxray/io/image.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/dicom_import.h"

namespace voxray::ui {

// 512 x 512 x 256 int16 (128 MiB): larger stacks take too long to decode for a preview.
constexpr size_t kThumbnailVoxelBudget = size_t(512) * 512 * 256;

struct SeriesScanEvents {
  std::function<void(const DicomListing&)> listed;
  std::function<void(int index, const Image& thumbnail)> thumbnail;  // empty: none possible
  std::function<void(const std::string& message)> failed;            // listing failed
  std::function<void()> finished;                                    // after the last one
};

class SeriesScan {
 public:
  // Starts at once. BUDGET: candidates with more voxels get an empty thumbnail.
  SeriesScan(std::string input, SeriesScanEvents events, size_t budget = kThumbnailVoxelBudget);
  ~SeriesScan();  // cancels and waits: no event arrives after this returns
  SeriesScan(const SeriesScan&) = delete;
  SeriesScan& operator=(const SeriesScan&) = delete;

 private:
  void run();

  std::string input_;
  SeriesScanEvents events_;
  size_t budget_;
  std::atomic<bool> cancel_{false};
  std::thread thread_;
};

}  // namespace voxray::ui
#endif
