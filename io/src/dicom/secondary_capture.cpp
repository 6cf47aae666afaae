#include "voxray/io/secondary_capture.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"

namespace voxray {

using dicomwrite::newUid;

std::string writeSecondaryCapture(const std::string& path, const std::vector<Image>& frames,
                                  const SecondaryCaptureInfo& info) {
  if (frames.empty() || frames[0].width <= 0 || frames[0].height <= 0 || frames[0].width > 65535 ||
      frames[0].height > 65535)
    throw inputError("A Secondary Capture needs at least one image of 1..65535 pixels a side");
  const int w = frames[0].width, h = frames[0].height;
  std::vector<Uint8> rgb;
  rgb.reserve(size_t(w) * size_t(h) * 3 * frames.size());
  for (const Image& f : frames) {
    if (f.width != w || f.height != h)
      throw inputError("The frames of a Secondary Capture must all be " + std::to_string(w) + "x" +
                       std::to_string(h) + " pixels");
    for (size_t i = 0; i < f.rgba.size(); i += 4) rgb.insert(rgb.end(), &f.rgba[i], &f.rgba[i + 3]);
  }
  const StudyIdentity& s = info.study;
  std::string sopUid = newUid(SITE_INSTANCE_UID_ROOT);
  DcmFileFormat file;
  DcmDataset* d = file.getDataset();
  auto put = [&](const DcmTagKey& tag, const std::string& value) {
    d->putAndInsertString(tag, value.c_str());
  };
  put(DCM_SpecificCharacterSet, "ISO_IR 192");  // StudyIdentity holds UTF-8
  put(DCM_SOPClassUID, UID_MultiframeTrueColorSecondaryCaptureImageStorage);
  put(DCM_SOPInstanceUID, sopUid);
  // The patient's name and ID are copied from the source on purpose: a PACS files an instance
  // by patient and study, and with an empty or other Patient ID the SC would not join its
  // study (Orthanc, for one, keys a study by Patient ID and Study Instance UID, so it would
  // make a second study of the same UID under another patient). Birth date and sex, Type 2
  // like them, are left empty alike: filing needs neither, and less patient data leaves the
  // workstation. These fields go into this header only: never into file names (the caller
  // chooses the path), messages or logs (DCMTK's log is off), nor into the pixels.
  put(DCM_PatientName, s.patientName);
  put(DCM_PatientID, s.patientId);
  put(DCM_PatientBirthDate, "");
  put(DCM_PatientSex, "");
  put(DCM_StudyInstanceUID,
      s.studyInstanceUid.empty() ? newUid(SITE_STUDY_UID_ROOT) : s.studyInstanceUid);
  put(DCM_StudyDate, s.studyDate);
  put(DCM_StudyTime, s.studyTime);
  put(DCM_StudyDescription, s.studyDescription);
  put(DCM_AccessionNumber, s.accessionNumber);
  put(DCM_ReferringPhysicianName, "");
  put(DCM_StudyID, s.studyId);
  put(DCM_Modality, "OT");
  put(DCM_SeriesInstanceUID,
      info.seriesInstanceUid.empty() ? newUid(SITE_SERIES_UID_ROOT) : info.seriesInstanceUid);
  put(DCM_SeriesNumber, "9000");
  put(DCM_Laterality, "");  // Type 2C: a screenshot may show a paired organ; not known here
  put(DCM_SeriesDescription, info.seriesDescription);
  put(DCM_Manufacturer, "Voxray");
  put(DCM_ConversionType, "WSD");  // workstation
  put(DCM_InstanceNumber, "1");
  put(DCM_PatientOrientation, "");
  put(DCM_ContentDate, dicomwrite::localNow("%Y%m%d"));
  put(DCM_ContentTime, dicomwrite::localNow("%H%M%S"));
  put(DCM_BurnedInAnnotation, info.burnedInAnnotation ? "YES" : "NO");
  put(DCM_ImageType, "DERIVED\\SECONDARY");
  if (!s.frameOfReferenceUid.empty()) put(DCM_FrameOfReferenceUID, s.frameOfReferenceUid);
  put(DCM_NumberOfFrames, std::to_string(frames.size()));
  // Frame Increment Pointer (Type 1C: only for more than one frame): frames follow one
  // another in time, FrameTime apart.
  if (frames.size() > 1) {
    d->putAndInsertTagKey(DCM_FrameIncrementPointer, DCM_FrameTime);
    put(DCM_FrameTime, "100");
  }
  d->putAndInsertUint16(DCM_SamplesPerPixel, 3);
  put(DCM_PhotometricInterpretation, "RGB");
  d->putAndInsertUint16(DCM_PlanarConfiguration, 0);
  d->putAndInsertUint16(DCM_Rows, Uint16(h));
  d->putAndInsertUint16(DCM_Columns, Uint16(w));
  d->putAndInsertUint16(DCM_BitsAllocated, 8);
  d->putAndInsertUint16(DCM_BitsStored, 8);
  d->putAndInsertUint16(DCM_HighBit, 7);
  d->putAndInsertUint16(DCM_PixelRepresentation, 0);
  d->putAndInsertUint8Array(DCM_PixelData, rgb.data(), rgb.size());
  dicomwrite::saveAtomically(file, path, "Secondary Capture");
  return sopUid;
}

}  // namespace voxray
