#include "voxray/io/phantom_series.h"

#include <algorithm>
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

#include <glm/gtc/matrix_transform.hpp>

#include "day_number.h"
#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

using dicomwrite::newUid;

std::string dsText(double v) {
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
      dsText(origin.x) + "\\" + dsText(origin.y) + "\\" + dsText(origin.z + k * spacing.z));
  put(DCM_SliceLocation, dsText(origin.z + k * spacing.z));
  put(DCM_PixelSpacing, dsText(spacing.y) + "\\" + dsText(spacing.x));
  put(DCM_SliceThickness, dsText(spacing.z));
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

double julianSeconds(const std::string& date, const std::string& time) {
  OFDate d;
  OFTime t;
  DcmDate::getOFDateFromString(date.c_str(), d);
  DcmTime::getOFTimeFromString(time.c_str(), t);
  return dicom::dayNumber(d) * 86400.0 + t.getTimeInSeconds();
}

// A CSA2 ("SV10") image header holding TAGS, each a name and its items as text: the layout
// Siemens writes into (0029,1010) and dcm2niix reads.
std::vector<Uint8> csaHeader(
    const std::vector<std::pair<std::string, std::vector<std::string>>>& tags) {
  std::vector<Uint8> out;
  auto u32 = [&](uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(Uint8(v >> (8 * b)));
  };
  for (char c : std::string("SV10\4\3\2\1")) out.push_back(Uint8(c));
  u32(uint32_t(tags.size()));
  u32(77);
  for (const auto& [name, items] : tags) {
    std::string field = name;
    field.resize(64, '\0');
    out.insert(out.end(), field.begin(), field.end());
    u32(uint32_t(items.size()));                                      // VM
    for (char c : std::string("IS\0\0", 4)) out.push_back(Uint8(c));  // VR (text either way)
    u32(6);                                                           // SyngoDT
    u32(uint32_t(items.size()));
    u32(77);
    for (const std::string& item : items) {
      const uint32_t length = uint32_t(item.size() + 1);  // with its terminating zero
      u32(length);
      u32(length);
      u32(77);
      u32(length);
      out.insert(out.end(), item.begin(), item.end());
      out.resize(out.size() + 1 + (4 - length % 4) % 4, 0);
    }
  }
  return out;
}

}  // namespace

glm::dmat3 MosaicPhantom::axes() const {
  const double toRad = 3.14159265358979323846 / 180.0;
  const glm::dmat4 turn =
      glm::rotate(glm::rotate(glm::dmat4(1.0), yawDegrees * toRad, glm::dvec3(0, 0, 1)),
                  pitchDegrees * toRad, glm::dvec3(1, 0, 0));
  glm::dmat3 a(turn);
  if (reverseSlices) a[2] = -a[2];
  return a;
}

glm::dvec3 MosaicPhantom::position(glm::ivec3 ijk) const {
  return originMm + axes() * (glm::dvec3(ijk) * spacingMm);
}

int MosaicPhantom::value(glm::ivec3 ijk, int timePoint) const {
  // The sphere's signal rises per time point; the background ramps along every axis, so a
  // swapped or flipped axis changes the values.
  if (glm::length(position(ijk) - sphereCentreMm) <= radiusMm) return 1000 + 150 * timePoint;
  return 100 + ijk.x + 2 * ijk.y + 3 * ijk.z + timePoint;
}

double petSphereSuv(const PetSpherePhantom& p) {
  double dose = p.injectedDoseBq;
  const double injected =
      p.injectionDateTime.size() >= 14
          ? julianSeconds(p.injectionDateTime.substr(0, 8), p.injectionDateTime.substr(8, 6))
          : julianSeconds(p.seriesDate, p.injectionTime);
  // The scan's start: the series time, unless the images were acquired before it (a series
  // made after the scan): then GE's private scan time when written, else the acquisition.
  double scan = julianSeconds(p.seriesDate, p.seriesTime);
  const double acquired = julianSeconds(p.seriesDate, p.acquisitionTime);
  if (acquired < scan)
    scan = p.geScanDateTime.size() >= 14
               ? julianSeconds(p.geScanDateTime.substr(0, 8), p.geScanDateTime.substr(8, 6))
               : acquired;
  if (p.decayCorrection == "START") dose *= std::pow(0.5, (scan - injected) / p.halfLifeS);
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
    if (!omitted("PatientWeight")) put(DCM_PatientWeight, dsText(p.weightKg));
    if (!p.geScanDateTime.empty()) {
      d->putAndInsertString(DcmTag(0x0009, 0x0010, EVR_LO), "GEMS_PETD_01");
      DcmTag scan(0x0009, 0x100D, EVR_DT);
      scan.setPrivateCreator("GEMS_PETD_01");
      d->putAndInsertString(scan, p.geScanDateTime.c_str());
    }
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
      drug->putAndInsertString(DCM_RadionuclideTotalDose, dsText(p.injectedDoseBq).c_str());
    if (!omitted("RadionuclideHalfLife"))
      drug->putAndInsertString(DCM_RadionuclideHalfLife, dsText(p.halfLifeS).c_str());
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
        put(DCM_TriggerTime, dsText(nominalInterval * t / p.phases));
        put(DCM_NominalInterval, dsText(nominalInterval));
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

namespace voxray {

void writeMosaicPhantom(const std::string& dir, const MosaicPhantom& p) {
  checkDims(p.dims, p.spacingMm);
  if (p.timePoints < 1 || p.timePoints > 100)
    throw inputError("phantom: time points must be 1..100");
  const int n = p.dims.z;
  const int across = int(std::ceil(std::sqrt(double(n)) - 1e-9));
  if (across * std::max(p.dims.x, p.dims.y) > 4096)
    throw inputError("phantom: the mosaic would be over 4096 pixels wide");
  prepareFolder(dir);
  SeriesHeader s;
  s.modality = "MR";
  s.sopClass = UID_MRImageStorage;
  s.description = "Mosaic fMRI phantom (" + std::to_string(p.timePoints) + " volumes)";
  s.date = "20260115";
  s.time = "140000";
  const glm::dmat3 a = p.axes();
  const glm::ivec2 whole = across * glm::ivec2(p.dims.x, p.dims.y);  // columns, rows
  // Siemens' Image Position: the corner of the whole tiled image, not of tile 0.
  const glm::dvec3 corner = p.position({0, 0, 0}) -
                            a[0] * (p.spacingMm.x * (whole.x - p.dims.x) / 2.0) -
                            a[1] * (p.spacingMm.y * (whole.y - p.dims.y) / 2.0);
  auto triple = [](const glm::dvec3& v) {
    return dsText(v.x) + "\\" + dsText(v.y) + "\\" + dsText(v.z);
  };
  const int images = p.mrHeaderImages.value_or(n);
  const int csaImages = p.csaImages.value_or(images);
  const glm::dvec3 sliceNormal = a[2];
  std::vector<Uint16> pixels(size_t(whole.x) * size_t(whole.y));
  for (int t = 0; t < p.timePoints; ++t) {
    DcmFileFormat file;
    DcmDataset* d = file.getDataset();
    Put put = [&](const DcmTagKey& tag, const std::string& value) {
      d->putAndInsertString(tag, value.c_str());
    };
    putCommon(d, s, put);
    d->findAndDeleteElement(DCM_RescaleSlope);  // MR has no Modality LUT module
    put(DCM_Manufacturer, "SIEMENS");           // the vendor whose private layout this copies
    put(DCM_ManufacturerModelName, "Voxray mosaic phantom");
    put(DCM_SoftwareVersions, "Voxray");
    // MR Image (PS3.3 C.8.3.1): a single-shot gradient-echo EPI, as fMRI is.
    put(DCM_ImageType, "ORIGINAL\\PRIMARY\\M\\ND\\MOSAIC");
    put(DCM_ScanningSequence, "EP");
    put(DCM_SequenceVariant, "SK");
    put(DCM_ScanOptions, "FS");
    put(DCM_MRAcquisitionType, "2D");
    put(DCM_SequenceName, "epfid2d1_" + std::to_string(p.dims.x));
    put(DCM_AngioFlag, "N");
    put(DCM_RepetitionTime, "2000");
    put(DCM_EchoTime, "30");
    put(DCM_EchoTrainLength, "1");
    put(DCM_NumberOfAverages, "1");
    put(DCM_ImagingFrequency, "123.2");
    put(DCM_ImagedNucleus, "1H");
    put(DCM_EchoNumbers, "1");
    put(DCM_MagneticFieldStrength, "3");
    put(DCM_FlipAngle, "90");
    put(DCM_InPlanePhaseEncodingDirection, "COL");
    put(DCM_SliceThickness, dsText(p.sliceThicknessMm));
    put(DCM_SpacingBetweenSlices, dsText(p.spacingMm.z));
    put(DCM_InstanceNumber, std::to_string(t + 1));
    put(DCM_AcquisitionNumber, std::to_string(t + 1));
    put(DCM_AcquisitionDate, s.date);
    char time[16];
    std::snprintf(time, sizeof time, "1400%02d.000000", 2 * t % 60);  // TR 2 s
    put(DCM_AcquisitionTime, time);
    put(DCM_ImagePositionPatient, triple(corner));
    put(DCM_ImageOrientationPatient, triple(a[0]) + "\\" + triple(a[1]));
    put(DCM_PixelSpacing, dsText(p.spacingMm.y) + "\\" + dsText(p.spacingMm.x));
    // Siemens' private attributes the split reads (dcm2niix reads the same).
    DcmTag creator19(0x0019, 0x0010, EVR_LO), creator29(0x0029, 0x0010, EVR_LO);
    d->putAndInsertString(creator19, "SIEMENS MR HEADER");
    if (p.writeMrHeaderImages) {
      DcmTag imagesTag(0x0019, 0x100A, EVR_US);
      imagesTag.setPrivateCreator("SIEMENS MR HEADER");
      d->putAndInsertUint16(imagesTag, Uint16(std::clamp(images, 0, 65535)));
    }
    d->putAndInsertString(creator29, "SIEMENS CSA HEADER");
    DcmTag headerType(0x0029, 0x1008, EVR_CS), headerVersion(0x0029, 0x1009, EVR_LO),
        header(0x0029, 0x1010, EVR_OB);
    for (DcmTag* tag : {&headerType, &headerVersion, &header})
      tag->setPrivateCreator("SIEMENS CSA HEADER");
    d->putAndInsertString(headerType, "IMAGE NUM 4");
    d->putAndInsertString(headerVersion, "20260115");
    const std::vector<Uint8> csa =
        csaHeader({{"NumberOfImagesInMosaic", {std::to_string(csaImages)}},
                   {"SliceNormalVector",
                    {dsText(sliceNormal.x), dsText(sliceNormal.y), dsText(sliceNormal.z)}}});
    d->putAndInsertUint8Array(header, csa.data(), Uint32(csa.size()));
    d->putAndInsertUint16(DCM_PixelRepresentation, 0);
    d->putAndInsertUint16(DCM_Rows, Uint16(whole.y));
    d->putAndInsertUint16(DCM_Columns, Uint16(whole.x));
    std::fill(pixels.begin(), pixels.end(), Uint16(0));  // tiles past the last slice stay 0
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < p.dims.y; ++j)
        for (int i = 0; i < p.dims.x; ++i) {
          const size_t row = size_t(k / across * p.dims.y + j),
                       col = size_t(k % across * p.dims.x + i);
          pixels[row * size_t(whole.x) + col] = Uint16(p.value({i, j, k}, t));
        }
    d->putAndInsertUint16Array(DCM_PixelData, pixels.data(), pixels.size());
    char name[32];
    std::snprintf(name, sizeof name, "MR%04d.dcm", t + 1);
    dicomwrite::saveAtomically(file, (fs::path(dir) / name).string(), "phantom mosaic");
  }
}

}  // namespace voxray
