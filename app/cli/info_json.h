#pragma once
// What `voxray-cli info --json` prints: the volume as loaded and, for DICOM, every candidate
// series. No patient data: info output may be pasted into tickets.
#include <nlohmann/json.hpp>

#include "voxray/io/dicom_import.h"
#include "voxray/io/volume.h"

namespace voxray::cli {

// LISTING may be null (raw data, or a build without DICOM).
// RANGE: the volume's stored range when the caller knows it (DicomImport::storedRange),
// saving a pass over every voxel; otherwise it is measured.
nlohmann::json infoJson(const Volume& v, const DicomListing* listing,
                        std::optional<ValueRange> range = std::nullopt);
// One time point's entry of `info --all-time-points --json` (the volume's fields alone).
nlohmann::json timePointJson(const Volume& v);

}  // namespace voxray::cli
