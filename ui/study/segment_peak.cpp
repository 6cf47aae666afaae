#include "segment_peak.h"

#include "voxray/engine/mask_peak.h"

namespace voxray {

void addSuvPeaks(std::vector<SegmentStats>& stats, const Segmentation& s, const Volume& v,
                 const Volume* overlay, const std::string& overlayName) {
  const bool onVolume = v.suv.has_value();
  if (!onVolume && !(overlay && overlay->suv)) return;
  const Volume& values = onVolume ? v : *overlay;
  for (SegmentStats& st : stats) {
    const RoiPeak peak =
        onVolume ? maskPeak(v, s.labels, st.label)
                 : maskPeak(*overlay, maskOnGrid(s.grid, s.labels, st.label, *overlay), 1);
    st.peakOf = onVolume ? "" : overlayName;
    if (peak.mean) {
      st.suvPeak = values.suv->toSuv(*peak.mean);
      st.peakNote.clear();
    } else {
      st.suvPeak.reset();
      st.peakNote = kNoRoomForPeakInSegment;
    }
  }
}

}  // namespace voxray
