#include "info_json.h"

namespace voxray::cli {
namespace {

nlohmann::json volumeJson(const Volume& v, std::optional<ValueRange> known = std::nullopt) {
  ValueRange r = known ? *known : storedRange(v);
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
          {"time_point", v.timePoint},
          {"time_points", v.timePoints},
          {"suv", v.suv ? nlohmann::json{{"factor", v.suv->factor}, {"unit", v.suv->unit}}
                        : nlohmann::json(nullptr)},
          {"warnings", v.warnings}};
}

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

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

nlohmann::json timePointJson(const Volume& v) { return volumeJson(v); }

nlohmann::json infoJson(const Volume& v, const DicomListing* listing,
                        std::optional<ValueRange> range) {
  nlohmann::json j = volumeJson(v, range);
  if (listing) {
    j["series"] = seriesJson(*listing);
    j["files_scanned"] = listing->filesScanned;
    j["files_skipped"] = listing->filesSkipped;
  }
  return j;
}

}  // namespace voxray::cli
