#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "input_options.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

namespace voxray::cli {

namespace {

nlohmann::json volumeJson(const Volume& v) {
  ValueRange r = storedRange(v);
  double a = v.toPhysical(r.min), b = v.toPhysical(r.max);
  nlohmann::json dir = nlohmann::json::array();
  for (int c = 0; c < 3; ++c) dir.push_back({v.direction[c].x, v.direction[c].y, v.direction[c].z});
  return {{"dims", {v.dims.x, v.dims.y, v.dims.z}},
          {"spacing_mm", {v.spacingMm.x, v.spacingMm.y, v.spacingMm.z}},
          {"origin_mm", {v.originMm.x, v.originMm.y, v.originMm.z}},
          {"direction", dir},
          {"hu_min", std::min(a, b)},
          {"hu_max", std::max(a, b)},
          {"unit", v.unit},
          {"sample_type", v.sourceType},
          {"rescale", {{"slope", v.slope}, {"intercept", v.intercept}}},
          {"bytes", v.byteSize()},
          {"warnings", v.warnings}};
}

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// Every candidate series, without patient data (info output may be pasted into tickets).
nlohmann::json seriesJson(const DicomListing& l) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : l.series) {
    nlohmann::json dir = nlohmann::json::array();
    for (int c = 0; c < 3; ++c) dir.push_back(vec(s.direction[c]));
    out.push_back({{"selector", s.selector},
                   {"uid", s.uid},
                   {"number", s.number},
                   {"description", s.description},
                   {"modality", s.modality},
                   {"transfer_syntax", s.transferSyntax},
                   {"dims", {s.dims.x, s.dims.y, s.dims.z}},
                   {"spacing_mm", vec(s.spacingMm)},
                   {"origin_mm", vec(s.originMm)},
                   {"direction", dir},
                   {"slice_count", s.sliceCount},
                   {"is_volume", s.isVolume},
                   {"chosen", s.chosenByDefault},
                   {"not_volume_reason", s.notVolumeReason},
                   {"warnings", s.warnings}});
  }
  return out;
}

}  // namespace

Run addInfoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Describe a volume: dims, spacing, value range, warnings");
  auto in = std::make_shared<InputOptions>();
  auto json = std::make_shared<bool>(false);
  in->add(*cmd);
  cmd->add_flag("--json", *json, "machine-readable output on stdout");
  return [in, json] {
    std::optional<DicomListing> listing;
#ifdef VOXRAY_HAS_DICOM  // lean builds (VOXRAY_WITH_DICOM=OFF) read raw data only
    if (!in->input.empty() && in->rawDims.empty()) {
      try {
        listing = listDicomSeries(in->input);
      } catch (const Error&) {
        // Not DICOM, or broken: loading below gives the message that says why.
      }
    }
#endif
    Volume v = in->load();
    nlohmann::json j = volumeJson(v);
    if (listing) {
      j["series"] = seriesJson(*listing);
      j["files_scanned"] = listing->filesScanned;
      j["files_skipped"] = listing->filesSkipped;
    }
    if (*json) {
      std::cout << j.dump(2) << "\n";
      return 0;
    }
    std::cout << "dims        " << v.dims.x << " x " << v.dims.y << " x " << v.dims.z << "\n"
              << "spacing     " << v.spacingMm.x << " x " << v.spacingMm.y << " x " << v.spacingMm.z
              << " mm\n"
              << "extent      " << v.extentMm().x << " x " << v.extentMm().y << " x "
              << v.extentMm().z << " mm\n"
              << "values      " << j["hu_min"].get<double>() << " ... " << j["hu_max"].get<double>()
              << " " << v.unit << "\n"
              << "sample type " << v.sourceType << " (stored as int16, " << (v.byteSize() >> 20)
              << " MiB)\n";
    for (const auto& w : v.warnings) std::cout << "warning: " << w << "\n";
    if (listing) {
      std::cout << "series (" << listing->filesScanned << " files, " << listing->filesSkipped
                << " skipped):\n";
      for (const auto& s : listing->series)
        std::cout << (s.chosenByDefault ? " * " : "   ") << s.selector << "  " << s.modality << "  "
                  << s.dims.x << "x" << s.dims.y << "x" << s.dims.z << "  " << s.description
                  << (s.isVolume ? "" : "  (" + s.notVolumeReason + ")") << "\n";
    }
    return 0;
  };
}

}  // namespace voxray::cli
