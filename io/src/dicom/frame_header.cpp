// Header parsing with DCMTK. Pixel data is never read here: parsing stops at PixelData, so
// listing a study touches only a few kilobytes per file.
#include "frame_header.h"

#include "bounded_load.h"
#include "private_tags.h"
#include "siemens_mosaic.h"
#include "text_decode.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string_view>

namespace voxray::dicom {
namespace {

// A guard against damaged headers: more frames than any real multi-frame object.
constexpr int kMaxFramesPerFile = 100000;

// Every string is UTF-8 from here on: JSON, the UI and messages need nothing else.
// VALUE: which value of a multi-valued element, or -1 for all of them as stored.
std::string str(DcmItem* item, const DcmTagKey& tag, const TextDecoder& text,
                bool personName = false, long value = -1) {
  OFString s;
  if (item && (value < 0 ? item->findAndGetOFStringArray(tag, s)
                         : item->findAndGetOFString(tag, s, static_cast<unsigned long>(value)))
                  .good()) {
    std::string out(s.data(), s.size());
    while (!out.empty() && (out.back() == ' ' || out.back() == '\0')) out.pop_back();
    return text(out, personName);
  }
  return {};
}

int intValue(DcmItem* item, const DcmTagKey& tag, int fallback = 0) {
  Sint32 s = 0;
  if (item && item->findAndGetSint32(tag, s).good()) return int(s);
  Uint16 u = 0;
  if (item && item->findAndGetUint16(tag, u).good()) return int(u);
  Uint32 ul = 0;
  if (item && item->findAndGetUint32(tag, ul).good()) return int(ul);
  return fallback;
}

// Reads N decimal values; false when any is missing or not finite.
bool doubles(DcmItem* item, const DcmTagKey& tag, double* out, int n) {
  if (!item) return false;
  for (int i = 0; i < n; ++i) {
    Float64 v = 0;
    if (item->findAndGetFloat64(tag, v, i).bad() || !std::isfinite(v)) return false;
    out[i] = v;
  }
  return true;
}

std::optional<int32_t> paddingValue(DcmItem* item, const DcmTagKey& tag, int pixelRep) {
  Uint16 u = 0;
  Sint16 s = 0;
  if (item->findAndGetUint16(tag, u).good()) return pixelRep ? int32_t(int16_t(u)) : int32_t(u);
  if (item->findAndGetSint16(tag, s).good()) return int32_t(s);
  return std::nullopt;
}

// The first item of sequence TAG inside a functional group item, if present.
DcmItem* group(DcmItem* groupItem, const DcmTagKey& seq) {
  DcmItem* found = nullptr;
  if (groupItem && groupItem->findAndGetSequenceItem(seq, found, 0).good()) return found;
  return nullptr;
}

// Per-frame groups win over shared ones (PS3.3 C.7.6.16).
DcmItem* frameGroup(DcmItem* perFrame, DcmItem* shared, const DcmTagKey& seq) {
  if (DcmItem* g = group(perFrame, seq)) return g;
  return group(shared, seq);
}

void readPlane(DcmItem* item, FrameHeader& h) {
  double p[3], o[6], sp[2];
  if (doubles(item, DCM_ImagePositionPatient, p, 3)) {
    h.position = {p[0], p[1], p[2]};
    h.hasPosition = true;
  }
  if (doubles(item, DCM_ImageOrientationPatient, o, 6)) {
    glm::dvec3 r{o[0], o[1], o[2]}, c{o[3], o[4], o[5]};
    if (glm::length(r) > 0.5 && glm::length(c) > 0.5 && glm::length(glm::cross(r, c)) > 0.5) {
      h.rowDir = glm::normalize(r);
      h.colDir = glm::normalize(c);
      h.hasOrientation = true;
    }
  }
  if (doubles(item, DCM_PixelSpacing, sp, 2) && sp[0] > 0 && sp[1] > 0) {
    h.pixelSpacing = {sp[1], sp[0]};  // DICOM gives row spacing (between rows) first
    h.hasPixelSpacing = true;
  }
  double v = 0;
  if (doubles(item, DCM_SliceThickness, &v, 1)) h.sliceThickness = v;
  if (doubles(item, DCM_SpacingBetweenSlices, &v, 1)) h.spacingBetweenSlices = v;
}

void readRescale(DcmItem* item, FrameHeader& h) {
  double v = 0;
  if (doubles(item, DCM_RescaleSlope, &v, 1) && v != 0.0) h.slope = v;
  if (doubles(item, DCM_RescaleIntercept, &v, 1)) h.intercept = v;
}

// The first WindowCenter/WindowWidth pair (a header may offer several, the first is the
// one meant by default) with its explanation. A width below 1 is no window (PS3.3
// C.11.2.1.2).
void readWindow(DcmItem* item, const TextDecoder& text, FrameHeader& h) {
  double centre = 0, width = 0;
  if (!doubles(item, DCM_WindowCenter, &centre, 1) || !doubles(item, DCM_WindowWidth, &width, 1) ||
      width < 1.0)
    return;
  h.window =
      DisplayWindow{width, centre, str(item, DCM_WindowCenterWidthExplanation, text, false, 0)};
}

void readFrameGroups(DcmItem* perFrame, DcmItem* shared, const TextDecoder& text, FrameHeader& h) {
  if (DcmItem* g = frameGroup(perFrame, shared, DCM_PlanePositionSequence)) readPlane(g, h);
  if (DcmItem* g = frameGroup(perFrame, shared, DCM_PlaneOrientationSequence)) readPlane(g, h);
  if (DcmItem* g = frameGroup(perFrame, shared, DCM_PixelMeasuresSequence)) readPlane(g, h);
  if (DcmItem* g = frameGroup(perFrame, shared, DCM_PixelValueTransformationSequence))
    readRescale(g, h);
  if (DcmItem* g = frameGroup(perFrame, shared, DCM_FrameVOILUTSequence)) readWindow(g, text, h);
  if (DcmItem* g = frameGroup(perFrame, shared, DCM_FrameContentSequence)) {
    h.temporalIndex = intValue(g, DCM_TemporalPositionIndex, 0);
    h.stackId = intValue(g, DCM_StackID, 0);
  }
}

std::optional<double> positive(DcmItem* item, const DcmTagKey& tag) {
  double v = 0;
  if (doubles(item, tag, &v, 1) && v > 0) return v;
  return std::nullopt;
}

// What SUV needs (suv.h); the times of the images themselves are added by the importer.
std::shared_ptr<const PetSuvAttributes> readPet(DcmDataset* ds, const TextDecoder& text) {
  auto p = std::make_shared<PetSuvAttributes>();
  p->units = str(ds, DCM_Units, text);
  p->decayCorrection = str(ds, DCM_DecayCorrection, text);
  p->seriesDate = str(ds, DCM_SeriesDate, text);
  p->seriesTime = str(ds, DCM_SeriesTime, text);
  p->weightKg = positive(ds, DCM_PatientWeight);
  p->geScanDateTime = text(privateText(ds, 0x0009, "GEMS_PETD_01", 0x0D), false);
  DcmItem* drug = nullptr;
  if (ds->findAndGetSequenceItem(DCM_RadiopharmaceuticalInformationSequence, drug, 0).good()) {
    p->injectionTime = str(drug, DCM_RadiopharmaceuticalStartTime, text);
    p->injectionDateTime = str(drug, DCM_RadiopharmaceuticalStartDateTime, text);
    p->injectedDoseBq = positive(drug, DCM_RadionuclideTotalDose);
    p->halfLifeS = positive(drug, DCM_RadionuclideHalfLife);
  }
  return p;
}

// "DICM" after the 128-byte preamble (PS3.10 7.1).
bool hasDicomPreamble(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char buf[132] = {};
  return in.read(buf, sizeof buf) && std::memcmp(buf + 128, "DICM", 4) == 0;
}

bool startsAsDicom(std::string_view bytes) {
  return bytes.size() >= 132 && bytes.substr(128, 4) == "DICM";
}

// The file's size in bytes, asked only when needed; nothing when it cannot be told.
using FileSize = std::function<std::optional<uintmax_t>()>;

// FAILURE: why FILE could not be parsed (empty when it was); PREAMBLE: whether the file
// starts as DICOM does.
ScanResult headersOf(DcmFileFormat& file, const std::string& failure,
                     const std::function<bool()>& preamble, const FileSize& fileSize,
                     const std::string& path, std::vector<FrameHeader>& out, std::string& why) {
  DcmDataset* ds = file.getDataset();
  if (!failure.empty() || !ds) {
    why = preamble() ? "damaged DICOM (" + failure + ")" : "not a DICOM file";
    return ScanResult::NotDicom;
  }
  const TextDecoder text(*ds);
  FrameHeader h;
  h.path = path;
  h.sopClassUid = str(ds, DCM_SOPClassUID, text);
  h.sopInstanceUid = str(ds, DCM_SOPInstanceUID, text);
  h.rows = intValue(ds, DCM_Rows);
  h.columns = intValue(ds, DCM_Columns);
  if (h.rows <= 0 || h.columns <= 0) {
    std::string media = str(file.getMetaInfo(), DCM_MediaStorageSOPClassUID, text);
    if (h.sopClassUid.empty() && media.empty() && str(ds, DCM_Modality, text).empty()) {
      why = "not a DICOM file";
      return ScanResult::NotDicom;
    }
    const char* name = dcmFindNameOfUID(media.empty() ? h.sopClassUid.c_str() : media.c_str());
    why = std::string("DICOM without an image (") + (name ? name : "no SOP class") + ")";
    return ScanResult::NoImage;
  }
  const DcmXfer xfer(ds->getOriginalXfer());
  h.transferSyntaxUid = xfer.getXferID();
  h.seriesUid = str(ds, DCM_SeriesInstanceUID, text);
  h.modality = str(ds, DCM_Modality, text);
  h.description = str(ds, DCM_SeriesDescription, text);
  h.imageType = str(ds, DCM_ImageType, text);
  h.photometric = str(ds, DCM_PhotometricInterpretation, text);
  h.seriesNumber = intValue(ds, DCM_SeriesNumber);
  h.instanceNumber = intValue(ds, DCM_InstanceNumber);
  h.acquisitionNumber = intValue(ds, DCM_AcquisitionNumber);
  h.temporalIndex = intValue(ds, DCM_TemporalPositionIdentifier);
  double trigger = 0;
  if (doubles(ds, DCM_TriggerTime, &trigger, 1)) h.triggerTime = trigger;
  h.acquisitionDate = str(ds, DCM_AcquisitionDate, text);
  h.acquisitionTime = str(ds, DCM_AcquisitionTime, text);
  if (h.modality == "PT") h.pet = readPet(ds, text);
  h.samplesPerPixel = intValue(ds, DCM_SamplesPerPixel, 1);
  h.planarConfiguration = intValue(ds, DCM_PlanarConfiguration, 0);
  h.bitsAllocated = intValue(ds, DCM_BitsAllocated, 16);
  h.bitsStored = intValue(ds, DCM_BitsStored, h.bitsAllocated);
  h.pixelRepresentation = intValue(ds, DCM_PixelRepresentation, 0);
  double tilt = 0;
  if (doubles(ds, DCM_GantryDetectorTilt, &tilt, 1)) h.gantryTilt = tilt;
  readPlane(ds, h);
  readRescale(ds, h);
  readWindow(ds, text, h);
  h.padding = paddingValue(ds, DCM_PixelPaddingValue, h.pixelRepresentation);
  h.paddingLimit = paddingValue(ds, DCM_PixelPaddingRangeLimit, h.pixelRepresentation);
  h.patientName = str(ds, DCM_PatientName, text, true);
  h.patientId = str(ds, DCM_PatientID, text);
  h.patientBirthDate = str(ds, DCM_PatientBirthDate, text);
  h.studyUid = str(ds, DCM_StudyInstanceUID, text);
  h.studyDate = str(ds, DCM_StudyDate, text);
  h.studyTime = str(ds, DCM_StudyTime, text);
  h.studyDescription = str(ds, DCM_StudyDescription, text, true);
  h.accession = str(ds, DCM_AccessionNumber, text);
  h.studyId = str(ds, DCM_StudyID, text);
  h.frameOfReferenceUid = str(ds, DCM_FrameOfReferenceUID, text);

  int frames = std::max(1, intValue(ds, DCM_NumberOfFrames, 1));
  if (frames > kMaxFramesPerFile) {
    why = "NumberOfFrames " + std::to_string(frames) + " is implausible; the file is damaged";
    return ScanResult::NoImage;
  }
  // Uncompressed frames lie one after another: a file too small for them is damaged, and
  // refusing it here keeps a header that claims 2000 frames from allocating them. A
  // deflated file (the whole dataset zlib-compressed) may well be smaller.
  if (!xfer.isEncapsulated() && xfer.getStreamCompression() == ESC_none) {
    const uintmax_t bits = uintmax_t(frames) * uintmax_t(h.rows) * uintmax_t(h.columns) *
                           uintmax_t(std::max(1, h.samplesPerPixel)) *
                           uintmax_t(std::max(1, h.bitsAllocated));
    const std::optional<uintmax_t> known = fileSize();
    const uintmax_t size = known.value_or(0);
    if (known && bits / 8 > size) {
      why = "the header describes " + std::to_string(frames) + " frame(s) of " +
            std::to_string(h.columns) + "x" + std::to_string(h.rows) + " pixels (" +
            std::to_string(bits / 8) + " bytes) but the file holds only " + std::to_string(size) +
            " bytes; the file is truncated or damaged";
      return ScanResult::NoImage;
    }
  }
  DcmItem* shared = nullptr;
  ds->findAndGetSequenceItem(DCM_SharedFunctionalGroupsSequence, shared, 0);
  DcmSequenceOfItems* perFrame = nullptr;
  ds->findAndGetSequence(DCM_PerFrameFunctionalGroupsSequence, perFrame);
  h.fileFrames = frames;
  h.perFrameGroups = shared || perFrame;
  const MosaicAttributes mosaic = readMosaicAttributes(ds, h.imageType);
  // Each tile becomes an image: as many as the frames of a multi-frame file may be at most.
  if (mosaic.images && int64_t(frames) * int64_t(std::max(1, *mosaic.images)) > kMaxFramesPerFile) {
    why = "a Siemens mosaic whose " + mosaic.imagesFrom + " is " + std::to_string(*mosaic.images) +
          (frames > 1 ? " in each of " + std::to_string(frames) + " frames" : std::string()) +
          ": more slices than any real series; the header is damaged";
    return ScanResult::NoImage;
  }
  std::vector<FrameHeader> images;
  for (int f = 0; f < frames; ++f) {
    FrameHeader fh = h;
    fh.frame = f;
    DcmItem* item = (perFrame && unsigned(f) < perFrame->card()) ? perFrame->getItem(f) : nullptr;
    if (shared || item) readFrameGroups(item, shared, text, fh);
    if (!mosaic.isMosaic) {
      images.push_back(std::move(fh));
    } else if (std::string wrong = splitMosaic(fh, mosaic, images); !wrong.empty()) {
      why = wrong;
      return ScanResult::NoImage;
    }
  }
  for (auto& image : images) out.push_back(std::move(image));
  return ScanResult::Image;
}

}  // namespace

ScanResult readFrameHeaders(const std::string& path, std::vector<FrameHeader>& out,
                            std::string& why) {
  DcmFileFormat file;
  uint64_t stoppedAt = 0;
  const std::string failure = loadDicomFile(file, path, 4096, DCM_PixelData, &stoppedAt);
  auto size = [&]() -> std::optional<uintmax_t> {
    std::error_code ec;
    const uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (ec) return std::nullopt;
    return bytes;
  };
  const size_t first = out.size();
  const ScanResult result = headersOf(
      file, failure, [&] { return hasDicomPreamble(path); }, size, path, out, why);
  for (size_t i = first; i < out.size(); ++i) out[i].pixelValueOffset = stoppedAt;
  return result;
}

ScanResult readFrameHeaders(const std::string& path, std::shared_ptr<const std::string> bytes,
                            DcmFileFormat& file, std::vector<FrameHeader>& out, std::string& why) {
  // BYTES stays held here: FILE keeps it only where a value was left in it.
  const std::string_view view = *bytes;
  const std::string failure = loadDicomBytes(file, bytes);
  return headersOf(
      file, failure, [&] { return startsAsDicom(view); },
      [&] { return std::optional<uintmax_t>(view.size()); }, path, out, why);
}

std::string transferSyntaxName(const std::string& uid) {
  DcmXfer xfer(uid.c_str());
  if (xfer.getXfer() == EXS_Unknown) return uid.empty() ? "unknown transfer syntax" : uid;
  return std::string(xfer.getXferName()) + " (" + uid + ")";
}

}  // namespace voxray::dicom
