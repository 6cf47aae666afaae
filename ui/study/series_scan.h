#pragma once
// The series picker's background work: list the series of a DICOM input (headers only),
// then make a thumbnail of each candidate's middle slice, one candidate at a time, on a
// thread of its own so the dialog stays responsive. Thumbnails load the candidate through
// importDicom (the only decoder io offers), so candidates above a voxel budget get none.
// Runs as a BackgroundTask: events arrive through POST (the picker's GUI thread).
#include <functional>
#include <string>

#include "background_task.h"
#include "no_qt.h"
#include "voxray/io/image.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/dicom_import.h"

namespace voxray {

// 512 x 512 x 256 int16 (128 MiB): larger stacks take too long to decode for a preview.
constexpr size_t kThumbnailVoxelBudget = size_t(512) * 512 * 256;

struct SeriesScanEvents {
  std::function<void(const DicomListing&)> listed;
  std::function<void(int index, const Image& thumbnail)> thumbnail;  // empty: none possible
  std::function<void(const std::string& message)> failed;            // listing failed
  std::function<void()> finished;                                    // after the last one
};

// The question to ask before opening S, or "" when S is a proper volume. The rule is the
// importer's own (SeriesInfo::isVolume, as voxray-cli info refuses such a series by default):
// the GUI asks instead of quietly loading a series that is no volume.
std::string notVolumeQuestion(const SeriesInfo& s);

class SeriesScan {
 public:
  // Starts at once. BUDGET: candidates with more voxels get an empty thumbnail. POST: where
  // events go (BackgroundTask::Post; none: on the scan's thread).
  SeriesScan(std::string input, SeriesScanEvents events, size_t budget = kThumbnailVoxelBudget,
             BackgroundTask::Post post = {});
  ~SeriesScan();  // cancels and waits: no event is sent after this returns
  SeriesScan(const SeriesScan&) = delete;
  SeriesScan& operator=(const SeriesScan&) = delete;

 private:
  void run();
  // Sends EVENT unless the scan was cancelled.
  void send(BackgroundTask::Event event) const;

  std::string input_;
  SeriesScanEvents events_;
  size_t budget_;
  BackgroundTask task_;  // last member: its thread starts after the rest is built
};

}  // namespace voxray
#endif
