// voxray_dicom_probe PATH [SERIES]: the listing and the loaded volume's geometry as JSON.
// Patient fields are left out on purpose: this output ends up in notes and logs.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

namespace {

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: voxray_dicom_probe PATH [SERIES]\n";
    return 2;
  }
  voxray::LoadOptions options;
  if (argc > 2) options.series = argv[2];
  nlohmann::json out;
  try {
    auto listing = voxray::listDicomSeries(argv[1], options);
    out["files_scanned"] = listing.filesScanned;
    out["files_skipped"] = listing.filesSkipped;
    out["notes"] = listing.notes;
    for (auto& s : listing.series)
      out["series"].push_back({{"selector", s.selector},
                               {"number", s.number},
                               {"modality", s.modality},
                               {"description", s.description},
                               {"dims", {s.dims.x, s.dims.y, s.dims.z}},
                               {"spacing_mm", vec(s.spacingMm)},
                               {"slices", s.sliceCount},
                               {"is_volume", s.isVolume},
                               {"chosen", s.chosenByDefault},
                               {"not_volume", s.notVolumeReason},
                               {"warnings", s.warnings},
                               {"transfer_syntax", s.transferSyntax}});
  } catch (const voxray::Error& e) {
    out["listing_error"] = e.what();
  }
  try {
    voxray::Volume v = voxray::importDicom(argv[1], options);
    auto range = std::minmax_element(v.voxels.begin(), v.voxels.end());
    out["volume"] = {{"dims", {v.dims.x, v.dims.y, v.dims.z}},
                     {"spacing_mm", vec(v.spacingMm)},
                     {"origin_mm", vec(v.originMm)},
                     {"direction", {vec(v.direction[0]), vec(v.direction[1]), vec(v.direction[2])}},
                     {"physical_min", v.toPhysical(*range.first)},
                     {"physical_max", v.toPhysical(*range.second)},
                     {"slope", v.slope},
                     {"intercept", v.intercept},
                     {"unit", v.unit},
                     {"warnings", v.warnings}};
  } catch (const voxray::Error& e) {
    out["load_error"] = e.what();
  }
  std::cout << out.dump(2) << "\n";
  return 0;
}
