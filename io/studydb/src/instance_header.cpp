#include "instance_header.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "dicom/bounded_load.h"
#include "dicom/text_decode.h"

namespace voxray::studydb {
namespace {

// Values longer than this are read only when asked for: none of the fields kept is.
constexpr Uint32 kMaxReadLength = 4096;

std::string str(DcmItem* item, const DcmTagKey& tag, const dicom::TextDecoder& text,
                bool personName = false) {
  OFString s;
  if (!item || item->findAndGetOFStringArray(tag, s).bad()) return {};
  std::string out(s.data(), s.size());
  while (!out.empty() && (out.back() == ' ' || out.back() == '\0')) out.pop_back();
  size_t start = out.find_first_not_of(' ');
  return text(start == std::string::npos ? std::string() : out.substr(start), personName);
}

int intValue(DcmItem* item, const DcmTagKey& tag, int fallback) {
  Sint32 s = 0;
  if (item->findAndGetSint32(tag, s).good()) return int(s);
  return fallback;
}

bool hasDicomPreamble(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char buf[132] = {};
  return in.read(buf, sizeof buf) && std::memcmp(buf + 128, "DICM", 4) == 0;
}

// Whether PATH can be DICOM at all, from its first bytes: the DICM preamble, or (a file
// without one, as old archives hold) a first element in group 0000, 0002, 0004 or 0008,
// either byte order. A folder of 10,000 other files (photos, reports, a video) is then
// skipped without DCMTK trying to parse each as a headerless dataset.
bool mayBeDicom(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char buf[132] = {};
  in.read(reinterpret_cast<char*>(buf), sizeof buf);
  const auto n = in.gcount();
  if (n == sizeof buf && std::memcmp(buf + 128, "DICM", 4) == 0) return true;
  if (n < 8) return false;
  for (unsigned group : {unsigned(buf[0] | buf[1] << 8), unsigned(buf[0] << 8 | buf[1])})
    if (group == 0x0000 || group == 0x0002 || group == 0x0004 || group == 0x0008) return true;
  return false;
}

}  // namespace

HeaderResult readInstanceHeader(const std::string& path, InstanceRecord& out, std::string& why) {
  if (!mayBeDicom(path)) {
    why = "not a DICOM file";
    return HeaderResult::NotDicom;
  }
  DcmFileFormat file;
  std::string failure = dicom::loadDicomFile(file, path, kMaxReadLength, DCM_PixelData);
  DcmDataset* ds = file.getDataset();
  if (!failure.empty() || !ds) {
    if (hasDicomPreamble(path)) {
      why = "damaged DICOM (" + failure + ")";
      return HeaderResult::Skipped;
    }
    why = "not a DICOM file";
    return HeaderResult::NotDicom;
  }
  const dicom::TextDecoder text(*ds);
  std::string media = str(file.getMetaInfo(), DCM_MediaStorageSOPClassUID, text);
  InstanceRecord r;
  r.instance.sopClassUid = str(ds, DCM_SOPClassUID, text);
  if (r.instance.sopClassUid.empty()) r.instance.sopClassUid = media;
  if (media == UID_MediaStorageDirectoryStorage) {
    why =
        "a DICOMDIR (its files are imported when they are under the folder, or when the "
        "DICOMDIR itself is given)";
    return HeaderResult::Skipped;
  }
  r.instance.sopInstanceUid = str(ds, DCM_SOPInstanceUID, text);
  r.study.uid = str(ds, DCM_StudyInstanceUID, text);
  r.series.uid = str(ds, DCM_SeriesInstanceUID, text);
  if (r.instance.sopInstanceUid.empty() || r.study.uid.empty() || r.series.uid.empty()) {
    if (r.instance.sopClassUid.empty() && str(ds, DCM_Modality, text).empty()) {
      why = hasDicomPreamble(path) ? "DICOM without an instance" : "not a DICOM file";
      return hasDicomPreamble(path) ? HeaderResult::Skipped : HeaderResult::NotDicom;
    }
    why = std::string("DICOM without a ") +
          (r.study.uid.empty()    ? "Study Instance UID"
           : r.series.uid.empty() ? "Series Instance UID"
                                  : "SOP Instance UID") +
          ": it cannot be placed in a study";
    return HeaderResult::Skipped;
  }
  r.patient.patientId = str(ds, DCM_PatientID, text);
  r.patient.name = str(ds, DCM_PatientName, text, true);
  r.patient.birthDate = str(ds, DCM_PatientBirthDate, text);
  r.patient.sex = str(ds, DCM_PatientSex, text);
  r.study.date = str(ds, DCM_StudyDate, text);
  r.study.time = str(ds, DCM_StudyTime, text);
  r.study.description = str(ds, DCM_StudyDescription, text);
  r.study.accession = str(ds, DCM_AccessionNumber, text);
  r.study.studyId = str(ds, DCM_StudyID, text);
  r.series.description = str(ds, DCM_SeriesDescription, text);
  r.series.modality = str(ds, DCM_Modality, text);
  r.series.bodyPart = str(ds, DCM_BodyPartExamined, text);
  r.series.number = intValue(ds, DCM_SeriesNumber, 0);
  r.instance.number = intValue(ds, DCM_InstanceNumber, 0);
  r.instance.frames = std::max(1, intValue(ds, DCM_NumberOfFrames, 1));
  r.instance.position = str(ds, DCM_ImagePositionPatient, text);
  // The syntax the file was written in (the meta header's, which names encapsulated ones).
  std::string ts = str(file.getMetaInfo(), DCM_TransferSyntaxUID, text);
  r.instance.transferSyntaxUid = ts.empty() ? DcmXfer(ds->getOriginalXfer()).getXferID() : ts;
  out = std::move(r);
  return HeaderResult::Instance;
}

}  // namespace voxray::studydb
