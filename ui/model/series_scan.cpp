#include "series_scan.h"

#ifdef VOXRAY_HAS_DICOM
#include "thumbnail.h"

namespace voxray::ui {

SeriesScan::SeriesScan(std::string input, SeriesScanEvents events, size_t budget)
    : input_(std::move(input)), events_(std::move(events)), budget_(budget) {
  thread_ = std::thread([this] { run(); });
}

SeriesScan::~SeriesScan() {
  cancel_ = true;
  thread_.join();
}

void SeriesScan::run() {
  LoadOptions options;
  options.cancel = &cancel_;
  DicomListing listing;
  try {
    listing = listDicomSeries(input_, options);
  } catch (const std::exception& e) {
    if (!cancel_ && events_.failed) events_.failed(e.what());
    return;
  }
  if (cancel_) return;
  if (events_.listed) events_.listed(listing);
  for (size_t i = 0; i < listing.series.size() && !cancel_; ++i) {
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
    if (!cancel_ && events_.thumbnail) events_.thumbnail(int(i), thumb);
  }
  if (!cancel_ && events_.finished) events_.finished();
}

}  // namespace voxray::ui
#endif
