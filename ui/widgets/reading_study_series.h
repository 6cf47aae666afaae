#pragma once
// The study folder's volume series, as the reading actions (reading_actions*.cpp) list them.
#ifdef VOXRAY_HAS_DICOM
#include <string>
#include <vector>

#include "app_models.h"
#include "voxray/io/dicom_import.h"

namespace voxray::ui::reading_detail {

// The study folder's volume series in the study's order, and which of them is open (-1: none).
std::vector<SeriesInfo> studyVolumes(const std::string& folder);
long openSeries(const std::vector<SeriesInfo>& volumes, const AppModels& m);

}  // namespace voxray::ui::reading_detail
#endif
