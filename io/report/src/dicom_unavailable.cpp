// Builds without DICOM (VOXRAY_WITH_DICOM=OFF): the DICOM results say what is missing.
#include "voxray/io/anonymise.h"
#include "voxray/io/error.h"
#include "voxray/io/key_object_selection.h"
#include "voxray/io/measurement_report.h"

namespace voxray {
namespace {
Error unavailable() {
  return inputError(
      "This Voxray was built without DICOM (VOXRAY_WITH_DICOM=OFF): rebuild with "
      "DCMTK to write DICOM SR, key images or anonymised copies");
}
}  // namespace

WrittenReport writeMeasurementReport(const std::string&, const Volume&,
                                     const std::vector<ReportMeasurement>&,
                                     const MeasurementReportInfo&) {
  throw unavailable();
}
std::string writeKeyObjectSelection(const std::string&, const Volume&, const std::vector<int>&,
                                    const KeyImagesInfo&) {
  throw unavailable();
}
AnonymiseResult anonymise(const std::string&, const std::string&, const AnonymiseOptions&) {
  throw unavailable();
}

}  // namespace voxray
