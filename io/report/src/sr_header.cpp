#include "sr_header.h"

namespace voxray::report {

void fileWithImages(DSRDocument& doc, const StudyIdentity& s, const std::string& seriesNumber,
                    const std::string& seriesDescription, const Check& check) {
  check(doc.setSpecificCharacterSetType(DSRTypes::CS_UTF8), "character set");
  check(doc.createNewSeriesInStudy(s.studyInstanceUid), "study");
  doc.setPatientName(s.patientName, OFFalse);
  doc.setPatientID(s.patientId, OFFalse);
  doc.setStudyDate(s.studyDate, OFFalse);
  doc.setStudyTime(s.studyTime, OFFalse);
  doc.setStudyDescription(s.studyDescription, OFFalse);
  doc.setAccessionNumber(s.accessionNumber, OFFalse);
  doc.setStudyID(s.studyId, OFFalse);
  if (!seriesDescription.empty()) doc.setSeriesDescription(seriesDescription, OFFalse);
  doc.setSeriesNumber(seriesNumber, OFFalse);
  doc.setInstanceNumber("1", OFFalse);
  doc.setManufacturer("Voxray", OFFalse);
}

void addEvidence(DSRDocument& doc, const StudyIdentity& s, const std::vector<int>& slices,
                 const Check& check) {
  for (int k : slices)
    check(doc.getCurrentRequestedProcedureEvidence().addItem(s.studyInstanceUid,
                                                             s.seriesInstanceUid, s.sopClassUid,
                                                             s.sliceSopInstanceUids[size_t(k)]),
          "evidence");
}

}  // namespace voxray::report
