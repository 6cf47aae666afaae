#include "series_scan.h"

#ifdef VOXRAY_HAS_DICOM
#include "thumbnail.h"
#include "voxray/io/error.h"

namespace voxray {

std::string notVolumeQuestion(const SeriesInfo& s) {
  if (s.isVolume) return {};
  return "Series " + s.selector + " is not a proper 3D volume: " + s.notVolumeReason +
         ".\nIt would open as a flat or distorted stack, not as the anatomy measured. "
         "Open it anyway?";
}

SeriesScan::SeriesScan(std::string input, SeriesScanEvents events, size_t budget,
                       BackgroundTask::Post post)
    : input_(std::move(input)),
      events_(std::move(events)),
      budget_(budget),
      task_(std::move(post)) {
  task_.start([this] { run(); });
}

SeriesScan::~SeriesScan() {
  task_.cancel();
  task_.wait();
}

void SeriesScan::send(BackgroundTask::Event event) const {
  if (!task_.cancelled()) task_.post(std::move(event));
}

void SeriesScan::run() {
  LoadOptions options;
  options.cancel = task_.cancelFlag();
  DicomListing listing;
  try {
    listing = listDicomSeries(input_, options);
  } catch (const std::exception& e) {
    if (!isCancellation(e) && events_.failed)
      send([f = events_.failed, m = std::string(e.what())] { f(m); });
    return;
  }
  if (task_.cancelled()) return;
  if (events_.listed) send([f = events_.listed, listing] { f(listing); });
  for (size_t i = 0; i < listing.series.size() && !task_.cancelled(); ++i) {
    const SeriesInfo& s = listing.series[i];
    Image thumb;
    size_t voxels = size_t(s.dims.x) * size_t(s.dims.y) * size_t(s.dims.z);
    if (voxels > 0 && voxels <= budget_) {
      try {
        options.series = s.selector;
        Volume v = importDicom(input_, options);
        thumb = middleSliceThumbnail(v, defaultThumbnailWindow(v, s.modality, s.isVolume));
      } catch (const std::exception&) {
        // Not loadable as a volume (a scout, a broken file): the row's notes say why.
      }
    }
    if (events_.thumbnail) send([f = events_.thumbnail, i, thumb] { f(int(i), thumb); });
  }
  if (events_.finished) send(events_.finished);
}

}  // namespace voxray
#endif
