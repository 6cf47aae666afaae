// Binary DICOM SEG through DCMTK's dcmseg (the library dcmqi and Slicer's exporter use).
#include <dcmtk/config/osconfig.h>  // first: DCMTK's configuration
#include <dcmtk/dcmdata/dctk.h>
#include <dcmtk/dcmfg/fgderimg.h>
#include <dcmtk/dcmfg/fgfracon.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmiod/cielabutil.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>
#include <dcmtk/oflog/oflog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <vector>

#include "formats.h"
#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"

namespace voxray::segfiles {
namespace {

using dicomwrite::newUid;

std::string ds(double v) {  // a DS value: at most 16 characters
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  std::string s = buf;
  if (s.size() > 16) {
    std::snprintf(buf, sizeof buf, "%.10g", v);
    s = buf;
  }
  return s;
}

void check(const OFCondition& c, const std::string& what) {
  if (c.bad()) throw outputError("DICOM SEG: " + what + " (" + c.text() + ")");
}

// Codes must be complete for the IOD; a free-text type keeps its meaning under a local code.
CodeSequenceMacro code(const Segment::Code& c, const Segment::Code& fallback) {
  if (!c.value.empty() && !c.scheme.empty() && !c.meaning.empty())
    return CodeSequenceMacro(c.value.c_str(), c.scheme.c_str(), c.meaning.c_str());
  if (!c.meaning.empty())
    return CodeSequenceMacro("VOXRAY-FREE-TEXT", "99VOXRAY", c.meaning.substr(0, 64).c_str());
  return CodeSequenceMacro(fallback.value.c_str(), fallback.scheme.c_str(),
                           fallback.meaning.c_str());
}

DcmSegTypes::E_SegmentAlgoType algorithmType(DicomSegOptions::Algorithm a) {
  switch (a) {
    case DicomSegOptions::Algorithm::Manual:
      return DcmSegTypes::SAT_MANUAL;
    case DicomSegOptions::Algorithm::Automatic:
      return DcmSegTypes::SAT_AUTOMATIC;
    default:
      return DcmSegTypes::SAT_SEMIAUTOMATIC;
  }
}

void requireUid(const std::string& uid, const char* what) {
  if (uid.empty())
    throw inputError(std::string("A DICOM SEG needs the source series' ") + what +
                     ", and this volume has none (it was not read from DICOM). Open the DICOM "
                     "series, or export NIfTI or .seg.nrrd instead.");
}

// The Referenced Series Sequence (Common Instance Reference Module) that viewers use to find
// the images a SEG lies on. DCMTK 3.6.7 leaves it to the caller.
void addReferencedSeries(DcmDataset& d, const StudyIdentity& source) {
  if (source.sliceSopInstanceUids.empty()) return;  // ReferencedInstanceSequence is type 1
  DcmItem* series = nullptr;
  check(d.findOrCreateSequenceItem(DCM_ReferencedSeriesSequence, series, 0),
        "cannot add the referenced series");
  series->putAndInsertString(DCM_SeriesInstanceUID, source.seriesInstanceUid.c_str());
  for (size_t k = 0; k < source.sliceSopInstanceUids.size(); ++k) {
    DcmItem* instance = nullptr;
    check(series->findOrCreateSequenceItem(DCM_ReferencedInstanceSequence, instance, long(k)),
          "cannot add a referenced instance");
    instance->putAndInsertString(DCM_ReferencedSOPClassUID, source.sopClassUid.c_str());
    instance->putAndInsertString(DCM_ReferencedSOPInstanceUID,
                                 source.sliceSopInstanceUids[k].c_str());
  }
}

}  // namespace

void quietDcmtkObjectLibraries() {
  static const bool once = [] {
    for (const char* name : {"dcmtk.dcmiod", "dcmtk.dcmfg", "dcmtk.dcmseg"})
      OFLog::getLogger(name).setLogLevel(OFLogger::ERROR_LOG_LEVEL);
    return true;
  }();
  (void)once;
}

WrittenDicomSeg writeSeg(const std::string& temporary, const Segmentation& seg,
                         const StudyIdentity& source, const DicomSegOptions& options) {
  quietDcmtkObjectLibraries();
  requireUid(source.studyInstanceUid, "Study Instance UID");
  requireUid(source.seriesInstanceUid, "Series Instance UID");
  requireUid(source.frameOfReferenceUid, "Frame of Reference UID");
  const VoxelGrid& g = seg.grid;
  if (g.dims.x > 65535 || g.dims.y > 65535)
    throw inputError("A DICOM SEG frame holds at most 65535 x 65535 pixels");
  const bool perSlice = !source.sliceSopInstanceUids.empty();
  if (perSlice && int(source.sliceSopInstanceUids.size()) != g.dims.z)
    throw inputError(
        "The segmentation has " + std::to_string(g.dims.z) + " slices but its source series " +
        std::to_string(source.sliceSopInstanceUids.size()) + ": it was not made on this series");
  if (seg.segments.empty()) throw inputError("The segmentation has no segment to export");

  // Which slices each label has voxels in: a frame per segment and such slice.
  const size_t sliceSize = size_t(g.dims.x) * size_t(g.dims.y);
  std::vector<std::array<bool, 256>> inSlice(size_t(g.dims.z));
  std::array<size_t, 256> voxels{};
  for (size_t k = 0; k < size_t(g.dims.z); ++k) {
    inSlice[k].fill(false);
    const uint8_t* s = seg.labels.data() + k * sliceSize;
    for (size_t i = 0; i < sliceSize; ++i) {
      inSlice[k][s[i]] = true;
      ++voxels[s[i]];
    }
  }
  for (const Segment& s : seg.segments)
    if (voxels[s.label] == 0)
      throw inputError("Segment \"" + s.name +
                       "\" is empty (0 voxels); a DICOM SEG segment needs at least one frame. "
                       "Paint it, or delete it before exporting.");

  IODGeneralEquipmentModule::EquipmentInfo equipment("Voxray", "Voxray", "1", "1.0");
  ContentIdentificationMacro content("1", "SEGMENTATION", options.seriesDescription.c_str(),
                                     "Voxray^");  // PN: family name^, not the retired one-part form
  DcmSegmentation* raw = nullptr;
  check(DcmSegmentation::createBinarySegmentation(raw, Uint16(g.dims.y), Uint16(g.dims.x),
                                                  equipment, content),
        "cannot create the segmentation object");
  std::unique_ptr<DcmSegmentation> doc(raw);

  // Same patient and study as the images it segments (the IOD requires it).
  doc->getSOPCommon().setSpecificCharacterSet("ISO_IR 192");  // StudyIdentity holds UTF-8
  doc->getPatient().setPatientName(source.patientName.c_str(), OFFalse);
  doc->getPatient().setPatientID(source.patientId.c_str(), OFFalse);
  doc->getPatient().setPatientBirthDate(source.patientBirthDate.c_str(), OFFalse);
  doc->getStudy().setStudyInstanceUID(source.studyInstanceUid.c_str(), OFFalse);
  doc->getStudy().setStudyDate(source.studyDate.c_str(), OFFalse);
  doc->getStudy().setStudyTime(source.studyTime.c_str(), OFFalse);
  doc->getStudy().setStudyID(source.studyId.c_str(), OFFalse);
  doc->getStudy().setAccessionNumber(source.accessionNumber.c_str(), OFFalse);
  doc->getStudy().setStudyDescription(source.studyDescription.c_str(), OFFalse);
  doc->getFrameOfReference().setFrameOfReferenceUID(source.frameOfReferenceUid.c_str(), OFFalse);
  const std::string seriesUid = newUid(SITE_SERIES_UID_ROOT);
  doc->getSeries().setSeriesInstanceUID(seriesUid.c_str());
  doc->getSeries().setSeriesNumber(std::to_string(options.seriesNumber).c_str());
  doc->getSeries().setSeriesDescription(options.seriesDescription.c_str(), OFFalse);
  const std::string sopUid = newUid(SITE_INSTANCE_UID_ROOT);
  doc->getSOPCommon().setSOPInstanceUID(sopUid.c_str());

  // What every frame shares: its pixel size and orientation.
  FGPixelMeasures measures;
  check(measures.setPixelSpacing((ds(g.spacingMm.y) + "\\" + ds(g.spacingMm.x)).c_str()),
        "pixel spacing");
  check(measures.setSliceThickness(ds(g.spacingMm.z).c_str()), "slice thickness");
  check(measures.setSpacingBetweenSlices(ds(g.spacingMm.z).c_str()), "spacing between slices");
  check(doc->addForAllFrames(measures), "pixel measures");
  std::unique_ptr<FGPlaneOrientationPatient> orientation(FGPlaneOrientationPatient::createMinimal(
      ds(g.direction[0].x).c_str(), ds(g.direction[0].y).c_str(), ds(g.direction[0].z).c_str(),
      ds(g.direction[1].x).c_str(), ds(g.direction[1].y).c_str(), ds(g.direction[1].z).c_str()));
  if (!orientation) throw outputError("DICOM SEG: cannot write the orientation");
  check(doc->addForAllFrames(*orientation), "plane orientation");

  const std::string dimensions = newUid(SITE_INSTANCE_UID_ROOT);
  check(doc->getDimensions().addDimensionIndex(DCM_ReferencedSegmentNumber, dimensions.c_str(),
                                               DCM_SegmentIdentificationSequence,
                                               "ReferencedSegmentNumber"),
        "dimension index");
  check(doc->getDimensions().addDimensionIndex(DCM_ImagePositionPatient, dimensions.c_str(),
                                               DCM_PlanePositionSequence, "ImagePositionPatient"),
        "dimension index");

  const Segment::Code tissue{"85756007", "SCT", "Tissue"};
  std::vector<Uint8> frame(sliceSize);
  // The pixel data as the standard packs it: every frame's bits one after another, the first
  // pixel in the lowest bit. DCMTK 3.6.7 misplaces the bits of frames that start inside a
  // byte (rows x columns not a multiple of 8); what it writes is replaced by these.
  size_t frames = 0;
  for (const Segment& s : seg.segments)
    for (const auto& labels : inSlice) frames += labels[s.label] ? 1 : 0;
  std::vector<Uint8> bits((frames * sliceSize + 7) / 8, 0);
  size_t bit = 0;
  for (const Segment& s : seg.segments) {
    DcmSegment* segment = nullptr;
    check(DcmSegment::create(
              segment, s.name.empty() ? "Segment" : s.name.substr(0, 64).c_str(),
              code(s.category, Segment::Code{"91723000", "SCT", "Anatomical Structure"}),
              code(s.type, tissue), algorithmType(options.algorithm),
              options.algorithm == DicomSegOptions::Algorithm::Manual
                  ? ""
                  : options.algorithmName.c_str()),
          "segment \"" + s.name + "\"");
    double L = 0, a = 0, b = 0;
    IODCIELabUtil::rgb2DicomLab(L, a, b, double(s.colour.r), double(s.colour.g),
                                double(s.colour.b));
    segment->setRecommendedDisplayCIELabValue(Uint16(std::lround(L)), Uint16(std::lround(a)),
                                              Uint16(std::lround(b)));
    Uint16 number = 0;
    check(doc->addSegment(segment, number), "segment \"" + s.name + "\"");

    for (int k = 0; k < g.dims.z; ++k) {
      if (!inSlice[size_t(k)][s.label]) continue;
      const uint8_t* labels = seg.labels.data() + size_t(k) * sliceSize;
      for (size_t i = 0; i < sliceSize; ++i) {
        frame[i] = labels[i] == s.label ? 1 : 0;
        if (frame[i]) bits[(bit + i) / 8] |= Uint8(1u << ((bit + i) % 8));
      }
      bit += sliceSize;
      const glm::dvec3 p = g.toPatient(glm::dvec3(0, 0, k));
      FGPlanePosPatient position;
      check(position.setImagePositionPatient(ds(p.x).c_str(), ds(p.y).c_str(), ds(p.z).c_str()),
            "frame position");
      FGFrameContent frameContent;
      frameContent.setDimensionIndexValues(number, 0);
      frameContent.setDimensionIndexValues(Uint32(k + 1), 1);
      OFVector<FGBase*> perFrame;
      perFrame.push_back(&position);
      perFrame.push_back(&frameContent);
      std::unique_ptr<FGDerivationImage> derivation;
      if (perSlice) {
        ImageSOPInstanceReferenceMacro ref;
        ref.setReferencedSOPClassUID(source.sopClassUid.c_str(), OFFalse);
        ref.setReferencedSOPInstanceUID(source.sliceSopInstanceUids[size_t(k)].c_str(), OFFalse);
        OFVector<ImageSOPInstanceReferenceMacro> refs;
        refs.push_back(ref);
        derivation.reset(FGDerivationImage::createMinimal(
            refs, "Segmentation", CodeSequenceMacro("113076", "DCM", "Segmentation"),
            CodeSequenceMacro("121322", "DCM", "Source image for image processing operation")));
        if (!derivation) throw outputError("DICOM SEG: cannot reference the source image");
        perFrame.push_back(derivation.get());
      }
      check(doc->addFrame(frame.data(), number, perFrame), "frame of slice " + std::to_string(k));
    }
  }

  DcmFileFormat file;
  check(doc->writeDataset(*file.getDataset()), "the object is not complete");
  bits.resize((bit + 7) / 8);
  if (bits.size() % 2) bits.push_back(0);  // DICOM values have even length
  check(file.getDataset()->putAndInsertUint8Array(DCM_PixelData, bits.data(),
                                                  (unsigned long)bits.size()),
        "pixel data");
  addReferencedSeries(*file.getDataset(), source);
  check(file.saveFile(temporary.c_str(), EXS_LittleEndianExplicit), "cannot write " + temporary);
  return {sopUid, seriesUid};
}

}  // namespace voxray::segfiles
