#include "voxray/io/phantom_series.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcvrda.h>
#include <dcmtk/dcmdata/dcvrtm.h>

#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

using dicomwrite::newUid;

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);  // DS holds 16 characters at most
  return text;
}

void prepareFolder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw outputError(dir + ": cannot create the folder (" + ec.message() + ")");
  if (!fs::is_empty(dir, ec))
    throw outputError(dir + ": the folder is not empty; give a new or empty folder");
}

// What every image of one series shares: patient, study, series, frame of reference, equipment.
struct SeriesHeader {
  std::string study = newUid(SITE_STUDY_UID_ROOT), series = newUid(SITE_SERIES_UID_ROOT),
              frame = newUid(SITE_INSTANCE_UID_ROOT);
  std::string modality, sopClass, description, date, time;
};

using Put = std::function<void(const DcmTagKey&, const std::string&)>;

void putCommon(DcmDataset* d, const SeriesHeader& s, const Put& put) {
  put(DCM_SOPClassUID, s.sopClass);
  put(DCM_SOPInstanceUID, newUid(SITE_INSTANCE_UID_ROOT));
  put(DCM_PatientName, "PHANTOM^VOXRAY");
  put(DCM_PatientID, "VOXRAY-PHANTOM");
  put(DCM_PatientBirthDate, "");
  put(DCM_PatientSex, "O");
  put(DCM_StudyInstanceUID, s.study);
  put(DCM_StudyDate, s.date);
  put(DCM_StudyTime, s.time);
  put(DCM_ReferringPhysicianName, "");
  put(DCM_StudyID, "1");
  put(DCM_AccessionNumber, "");
  put(DCM_StudyDescription, "Voxray phantom");
  put(DCM_Modality, s.modality);
  put(DCM_SeriesInstanceUID, s.series);
  put(DCM_SeriesNumber, "1");
  put(DCM_SeriesDescription, s.description);
  put(DCM_Laterality, "");  // Type 2C: a body, no paired organ
  put(DCM_FrameOfReferenceUID, s.frame);
  put(DCM_PositionReferenceIndicator, "");
  put(DCM_Manufacturer, "Voxray");
  // PET says it by its code sequences instead (C.8.4.6), where Patient Position is not allowed.
  if (s.modality != "PT") put(DCM_PatientPosition, "HFS");
  put(DCM_ContentDate, s.date);
  put(DCM_ContentTime, s.time);
  put(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
  put(DCM_SamplesPerPixel, "1");
  put(DCM_PhotometricInterpretation, "MONOCHROME2");
  d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
  d->putAndInsertUint16(DCM_BitsAllocated, 16);
  d->putAndInsertUint16(DCM_BitsStored, 16);
  d->putAndInsertUint16(DCM_HighBit, 15);
  put(DCM_RescaleSlope, "1");
}

void putSlice(DcmDataset* d, const Put& put, glm::ivec3 dims, glm::dvec3 spacing, int k,
              const std::vector<Uint16>& pixels) {
  // LPS, axial: the volume centred on the origin, slice k at z = (k - centre) * spacing.
  const glm::dvec3 origin = -0.5 * glm::dvec3(dims - 1) * spacing;
  put(DCM_ImagePositionPatient,
      number(origin.x) + "\\" + number(origin.y) + "\\" + number(origin.z + k * spacing.z));
  put(DCM_SliceLocation, number(origin.z + k * spacing.z));
  put(DCM_PixelSpacing, number(spacing.y) + "\\" + number(spacing.x));
  put(DCM_SliceThickness, number(spacing.z));
  d->putAndInsertUint16(DCM_Rows, Uint16(dims.y));
  d->putAndInsertUint16(DCM_Columns, Uint16(dims.x));
  d->putAndInsertUint16Array(DCM_PixelData, pixels.data(), pixels.size());
}

// Distance of voxel (i, j, k)'s centre from the volume's centre, in mm.
double fromCentre(glm::ivec3 dims, glm::dvec3 spacing, int i, int j, int k) {
  return glm::length((glm::dvec3(i, j, k) - 0.5 * glm::dvec3(dims - 1)) * spacing);
}

void checkDims(glm::ivec3 dims, glm::dvec3 spacing) {
  if (glm::any(glm::lessThan(dims, glm::ivec3(2))) || dims.x > 4096 || dims.y > 4096 ||
      dims.z > 4096 || !(glm::all(glm::greaterThan(spacing, glm::dvec3(0)))))
    throw inputError("phantom: dims must be 2..4096 and spacing positive");
}

// Days since 1970-01-01 of D (its calendar date).
double dayNumber(const OFDate& d) {
  using namespace std::chrono;
  return double(
      sys_days(year_month_day(year(int(d.getYear())), month(d.getMonth()), day(d.getDay())))
          .time_since_epoch()
          .count());
}

double julianSeconds(const std::string& date, const std::string& time) {
  OFDate d;
  OFTime t;
  DcmDate::getOFDateFromString(date.c_str(), d);
  DcmTime::getOFTimeFromString(time.c_str(), t);
  return dayNumber(d) * 86400.0 + t.getTimeInSeconds();
}

}  // namespace

double petSphereSuv(const PetSpherePhantom& p) {
  double dose = p.injectedDoseBq;
  const double injected =
      p.injectionDateTime.size() >= 14
          ? julianSeconds(p.injectionDateTime.substr(0, 8), p.injectionDateTime.substr(8, 6))
          : julianSeconds(p.seriesDate, p.injectionTime);
  if (p.decayCorrection == "START")
    dose *= std::pow(0.5, (julianSeconds(p.seriesDate, p.seriesTime) - injected) / p.halfLifeS);
  return p.insideBqml * p.weightKg * 1000.0 / dose;
}

void writePetSpherePhantom(const std::string& dir, const PetSpherePhantom& p) {
  checkDims(p.dims, p.spacingMm);
  if (p.insideBqml < 0 || p.insideBqml > 65535 || p.backgroundBqml < 0 || p.backgroundBqml > 65535)
    throw inputError("phantom: activities must be 0..65535 Bq/mL (16-bit, slope 1)");
  prepareFolder(dir);
  SeriesHeader s;
  s.modality = "PT";
  s.sopClass = UID_PositronEmissionTomographyImageStorage;
  s.description = "PET sphere phantom";
  s.date = p.seriesDate;
  s.time = p.seriesTime;
  auto omitted = [&](const char* keyword) { return p.omit.count(keyword) > 0; };
  for (int k = 0; k < p.dims.z; ++k) {
    DcmFileFormat file;
    DcmDataset* d = file.getDataset();
    Put put = [&](const DcmTagKey& tag, const std::string& value) {
      d->putAndInsertString(tag, value.c_str());
    };
    putCommon(d, s, put);
    if (!omitted("PatientWeight")) put(DCM_PatientWeight, number(p.weightKg));
    // PET Series (PS3.3 C.8.9.1).
    put(DCM_SeriesDate, p.seriesDate);
    if (!omitted("SeriesTime")) put(DCM_SeriesTime, p.seriesTime);
    if (!omitted("Units")) put(DCM_Units, "BQML");
    put(DCM_CountsSource, "EMISSION");
    put(DCM_SeriesType, "STATIC\\IMAGE");
    d->putAndInsertUint16(DCM_NumberOfSlices, Uint16(p.dims.z));
    put(DCM_CorrectedImage, p.decayCorrection == "NONE" ? "ATTN" : "DECY\\ATTN");
    if (!omitted("DecayCorrection")) put(DCM_DecayCorrection, p.decayCorrection);
    put(DCM_CollimatorType, "NONE");
    // PET Isotope (C.8.9.2): fluorine-18 FDG.
    DcmItem* drug = nullptr;
    d->findOrCreateSequenceItem(DCM_RadiopharmaceuticalInformationSequence, drug, 0);
    if (!omitted("RadiopharmaceuticalStartTime"))
      drug->putAndInsertString(DCM_RadiopharmaceuticalStartTime, p.injectionTime.c_str());
    if (!p.injectionDateTime.empty())
      drug->putAndInsertString(DCM_RadiopharmaceuticalStartDateTime, p.injectionDateTime.c_str());
    if (!omitted("RadionuclideTotalDose"))
      drug->putAndInsertString(DCM_RadionuclideTotalDose, number(p.injectedDoseBq).c_str());
    if (!omitted("RadionuclideHalfLife"))
      drug->putAndInsertString(DCM_RadionuclideHalfLife, number(p.halfLifeS).c_str());
    drug->putAndInsertString(DCM_Radiopharmaceutical, "Fluorodeoxyglucose F^18^");
    DcmItem* nuclide = nullptr;
    drug->findOrCreateSequenceItem(DCM_RadionuclideCodeSequence, nuclide, 0);
    nuclide->putAndInsertString(DCM_CodeValue, "C-111A1");
    nuclide->putAndInsertString(DCM_CodingSchemeDesignator, "SRT");
    nuclide->putAndInsertString(DCM_CodeMeaning, "^18^Fluorine");
    // NM/PET Patient Orientation (C.8.4.6): Type 2, known here.
    DcmItem* orientation = nullptr;
    d->findOrCreateSequenceItem(DCM_PatientOrientationCodeSequence, orientation, 0);
    orientation->putAndInsertString(DCM_CodeValue, "F-10450");
    orientation->putAndInsertString(DCM_CodingSchemeDesignator, "SRT");
    orientation->putAndInsertString(DCM_CodeMeaning, "recumbent");
    DcmItem* gantry = nullptr;
    d->findOrCreateSequenceItem(DCM_PatientGantryRelationshipCodeSequence, gantry, 0);
    gantry->putAndInsertString(DCM_CodeValue, "F-10470");
    gantry->putAndInsertString(DCM_CodingSchemeDesignator, "SRT");
    gantry->putAndInsertString(DCM_CodeMeaning, "headfirst");
    // PET Image (C.8.9.4).
    put(DCM_ImageType, "ORIGINAL\\PRIMARY");
    put(DCM_InstanceNumber, std::to_string(k + 1));
    d->putAndInsertUint16(DCM_ImageIndex, Uint16(k + 1));
    d->putAndInsertUint16(DCM_PixelRepresentation, 0);
    put(DCM_RescaleIntercept, "0");
    put(DCM_FrameReferenceTime, "0");
    put(DCM_AcquisitionDate, p.seriesDate);
    put(DCM_AcquisitionTime, p.acquisitionTime);
    put(DCM_ActualFrameDuration, "300000");
    if (p.decayCorrection != "NONE") put(DCM_DecayFactor, "1");
    put(DCM_LossyImageCompression, "00");
    std::vector<Uint16> pixels(size_t(p.dims.x) * size_t(p.dims.y));
    for (int j = 0; j < p.dims.y; ++j)
      for (int i = 0; i < p.dims.x; ++i)
        pixels[size_t(j) * size_t(p.dims.x) + size_t(i)] =
            Uint16(fromCentre(p.dims, p.spacingMm, i, j, k) <= p.radiusMm ? p.insideBqml
                                                                          : p.backgroundBqml);
    putSlice(d, put, p.dims, p.spacingMm, k, pixels);
    char name[32];
    std::snprintf(name, sizeof name, "PT%04d.dcm", k + 1);
    dicomwrite::saveAtomically(file, (fs::path(dir) / name).string(), "phantom slice");
  }
}

double BeatingSpherePhantom::radiusAt(int phase) const {
  constexpr double kPi = 3.14159265358979323846;
  return radiusMm + amplitudeMm * std::sin(2.0 * kPi * phase / phases);
}

void writeBeatingSpherePhantom(const std::string& dir, const BeatingSpherePhantom& p) {
  checkDims(p.dims, p.spacingMm);
  if (p.phases < 1 || p.phases > 100) throw inputError("phantom: phases must be 1..100");
  if (p.timing != "temporal" && p.timing != "trigger" && p.timing != "repeated")
    throw inputError("phantom: timing '" + p.timing + "': give temporal, trigger or repeated");
  prepareFolder(dir);
  SeriesHeader s;
  s.modality = "CT";
  s.sopClass = UID_CTImageStorage;
  s.description = "Beating sphere phantom (" + std::to_string(p.phases) + " phases)";
  s.date = "20260115";
  s.time = "120000";
  const double nominalInterval = 800.0;  // ms: one heart beat at 75 per minute
  std::vector<Uint16> pixels(size_t(p.dims.x) * size_t(p.dims.y));
  for (int t = 0; t < p.phases; ++t) {
    const double r = p.radiusAt(t);
    for (int k = 0; k < p.dims.z; ++k) {
      DcmFileFormat file;
      DcmDataset* d = file.getDataset();
      Put put = [&](const DcmTagKey& tag, const std::string& value) {
        d->putAndInsertString(tag, value.c_str());
      };
      putCommon(d, s, put);
      // Phase-major instance numbers: the images of one position are phases apart. "trigger"
      // numbers them backwards, so only Trigger Time can order the phases.
      const int order = t * p.dims.z + k;
      const int instance = p.timing == "trigger" ? p.phases * p.dims.z - order : order + 1;
      put(DCM_ImageType, "ORIGINAL\\PRIMARY\\AXIAL");
      put(DCM_InstanceNumber, std::to_string(instance));
      put(DCM_AcquisitionNumber, "1");
      put(DCM_KVP, "120");
      put(DCM_AcquisitionDate, s.date);
      put(DCM_AcquisitionTime, s.time);
      if (p.timing == "temporal") {
        put(DCM_TemporalPositionIdentifier, std::to_string(t + 1));
        put(DCM_NumberOfTemporalPositions, std::to_string(p.phases));
      }
      if (p.timing != "repeated") {
        put(DCM_TriggerTime, number(nominalInterval * t / p.phases));
        put(DCM_NominalInterval, number(nominalInterval));
        put(DCM_CardiacNumberOfImages, std::to_string(p.phases));
      }
      d->putAndInsertUint16(DCM_PixelRepresentation, 1);
      put(DCM_RescaleIntercept, "0");
      put(DCM_RescaleType, "HU");
      for (int j = 0; j < p.dims.y; ++j)
        for (int i = 0; i < p.dims.x; ++i)
          pixels[size_t(j) * size_t(p.dims.x) + size_t(i)] = Uint16(
              Sint16(fromCentre(p.dims, p.spacingMm, i, j, k) <= r ? p.insideHu : p.outsideHu));
      putSlice(d, put, p.dims, p.spacingMm, k, pixels);
      char name[32];
      std::snprintf(name, sizeof name, "CT%05d.dcm", instance);
      dicomwrite::saveAtomically(file, (fs::path(dir) / name).string(), "phantom slice");
    }
  }
}

}  // namespace voxray
