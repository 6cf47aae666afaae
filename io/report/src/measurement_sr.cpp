// The TID 1500 Measurement Report through DCMTK's template classes (dcmsr/cmr): they add the
// content items in the template's order with its relationships, and check each value.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmsr/cmr/tid1500.h>
#include <dcmtk/dcmsr/codes/dcm.h>
#include <dcmtk/dcmsr/codes/sct.h>
#include <dcmtk/dcmsr/dsrdoc.h>

#include "sr_header.h"
#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"
#include "voxray/io/measurement_report.h"

namespace voxray {
namespace {

using Group = CMR_TID1501_in_TID1500;
using Value = Group::MeasurementValue;

void check(const OFCondition& c, const std::string& what) {
  if (c.bad())
    throw outputError("Cannot build the measurement report (" + what + ": " + c.text() +
                      "); please report this with the measurement that caused it");
}

// DS holds 16 characters: 9 significant digits always fit with sign, point and exponent.
std::string ds(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

// The concept and unit of ROI values: CT in HU, PET in SUVbw when the volume has the scale,
// MR as its unitless signal; other values have no coded concept here.
struct Quantity {
  DSRCodedEntryValue name, unit;
};

Quantity roiQuantity(const Volume& v) {
  if (v.suv)
    return {DSRCodedEntryValue("126401", "DCM", "SUVbw"),
            DSRCodedEntryValue("g/ml{SUVbw}", "UCUM", "Standardized Uptake Value body weight")};
  if (v.unit == "HU")
    return {DSRCodedEntryValue(CODE_DCM_AttenuationCoefficient),
            DSRCodedEntryValue("[hnsf'U]", "UCUM", "Hounsfield Unit")};
  if (v.modality == "MR")
    return {DSRCodedEntryValue("110852", "DCM", "MR signal intensity"),
            DSRCodedEntryValue("1", "UCUM", "no units")};
  throw inputError(
      "The report names ROI values in HU (CT), SUVbw (PET with its dose and weight) "
      "or MR signal; this volume's values (" +
      v.unit +
      ") are none of them: "
      "export the measurements as CSV instead");
}

// SCOORD pixel coordinates: (column, row) with (0, 0) the top left corner of the top left
// pixel, so a voxel centre i is at i + 0.5.
DSRSpatialCoordinatesValue scoord(const ReportMeasurement& m) {
  auto px = [](double i) { return Float32(i + 0.5); };
  if (m.kind == ReportKind::Length || m.kind == ReportKind::Angle) {
    DSRSpatialCoordinatesValue s(DSRTypes::GT_Polyline);
    for (const auto& p : m.points) s.getGraphicDataList().addItem(px(p.x), px(p.y));
    return s;
  }
  const glm::dvec3 &a = m.points[0], &b = m.points[1];
  if (m.kind == ReportKind::Rect) {
    // A closed POLYLINE is the 2D SCOORD's polygon.
    DSRSpatialCoordinatesValue s(DSRTypes::GT_Polyline);
    const double xs[] = {a.x, b.x, b.x, a.x, a.x}, ys[] = {a.y, a.y, b.y, b.y, a.y};
    for (int n = 0; n < 5; ++n) s.getGraphicDataList().addItem(px(xs[n]), px(ys[n]));
    return s;
  }
  // ELLIPSE: the major axis' two ends, then the minor axis' (PS3.3 C.18.6.1.2).
  DSRSpatialCoordinatesValue s(DSRTypes::GT_Ellipse);
  const double cx = (a.x + b.x) / 2, cy = (a.y + b.y) / 2;
  const double rx = std::abs(b.x - a.x) / 2, ry = std::abs(b.y - a.y) / 2;
  auto add = [&](double x, double y) { s.getGraphicDataList().addItem(px(x), px(y)); };
  if (rx >= ry) {
    add(cx - rx, cy), add(cx + rx, cy), add(cx, cy - ry), add(cx, cy + ry);
  } else {
    add(cx, cy - ry), add(cx, cy + ry), add(cx - rx, cy), add(cx + rx, cy);
  }
  return s;
}

// The slices (k) of the volume a measurement's points lie on, when they are its files' images.
std::vector<int> touchedSlices(const Volume& v, const ReportMeasurement& m) {
  std::vector<int> out;
  if (int(v.study.sliceSopInstanceUids.size()) != v.dims.z) return out;
  const int one = measurementSlice(m);
  if (one >= 0) {
    if (one < v.dims.z) out.push_back(one);
    return out;
  }
  for (const auto& p : m.points) {
    const int k = int(std::lround(p.z));
    if (k >= 0 && k < v.dims.z && std::find(out.begin(), out.end(), k) == out.end())
      out.push_back(k);
  }
  return out;
}

}  // namespace

WrittenReport writeMeasurementReport(const std::string& path, const Volume& v,
                                     const std::vector<ReportMeasurement>& measurements,
                                     const MeasurementReportInfo& info) {
  const StudyIdentity& s = v.study;
  if (s.studyInstanceUid.empty() || s.seriesInstanceUid.empty() || s.sopClassUid.empty())
    throw inputError(
        "A DICOM SR references the images it measures: open a DICOM series (this volume was "
        "not read from DICOM); export the measurements as CSV instead");
  if (measurements.empty())
    throw inputError("The measurement report needs at least one measurement");
  WrittenReport out;
  const bool perSlice = int(s.sliceSopInstanceUids.size()) == v.dims.z;
  if (!perSlice)
    out.notes.push_back(
        "the volume's slices are not its files' images (resampled, or frames of one file): the "
        "report is filed in the series' study but names no image and has no image coordinates");

  TID1500_MeasurementReport report(CMR_CID7021::ImagingMeasurementReport);
  check(report.setLanguage(CID5000_Languages::English, CID5001_Countries::UnitedStates),
        "language");
  check(report.getObservationContext().addDeviceObserver(dicomwrite::newUid(SITE_INSTANCE_UID_ROOT),
                                                         "Voxray", "Voxray"),
        "observer");
  check(report.addProcedureReported(CMR_CID100(DSRCodedEntryValue(CODE_SCT_ImagingProcedure))),
        "procedure");
  // The image library lists every image a measurement references, once.
  std::vector<int> slices;
  for (const auto& m : measurements)
    for (int k : touchedSlices(v, m))
      if (std::find(slices.begin(), slices.end(), k) == slices.end()) slices.push_back(k);
  check(report.getImageLibrary().createNewImageLibrary(), "image library");
  if (!slices.empty()) check(report.getImageLibrary().addImageGroup(), "image library group");
  for (int k : slices) {
    DcmItem image;
    image.putAndInsertString(DCM_SOPClassUID, s.sopClassUid.c_str());
    image.putAndInsertString(DCM_SOPInstanceUID, s.sliceSopInstanceUids[size_t(k)].c_str());
    check(report.getImageLibrary().addImageEntry(image, TID1600_ImageLibrary::withoutDescriptors),
          "image library entry");
  }

  const Quantity roi = roiQuantity(v);
  int number = 0;
  for (const auto& m : measurements) {
    ++number;
    const std::string label = m.label.empty() ? "measurement " + std::to_string(number) : m.label;
    const int k = measurementSlice(m);
    const bool onImage = perSlice && k >= 0 && k < v.dims.z;
    const std::vector<int> touched = touchedSlices(v, m);
    if (m.kind == ReportKind::Segment)
      out.notes.push_back(label + ": a segment's values reference the series, not its images");
    else if (perSlice && !onImage)
      out.notes.push_back(label + ": its points lie on " + std::to_string(touched.size()) +
                          " slices; it references their images without image coordinates");
    check(report.addIndividualMeasurements(), "measurement group");
    Group& group = report.getIndividualMeasurements();
    check(group.setTrackingIdentifier(label), "tracking identifier");
    check(group.setTrackingUniqueIdentifier(dicomwrite::newUid(SITE_INSTANCE_UID_ROOT)),
          "tracking UID");
    // One TID 300 per value, each with the image region it was measured in.
    auto add = [&](const DSRCodedEntryValue& name, double x, const DSRCodedEntryValue& unit,
                   const CID7464_GeneralRegionOfInterestMeasurementModifiers* derivation) {
      check(
          group.addMeasurement(CMR_CID7469(name), Value(ds(x), CMR_CID7181(unit)), OFTrue, OFTrue),
          label + " value");
      auto& value = group.getMeasurement();
      if (derivation) check(value.setDerivation(*derivation), label + " derivation");
      if (m.kind == ReportKind::Segment) {
        // A label map has no SCOORD: the values name the series (the evidence) only.
      } else if (onImage) {
        DSRImageReferenceValue image(s.sopClassUid, s.sliceSopInstanceUids[size_t(k)]);
        check(value.addSpatialCoordinates(CODE_DCM_ImageRegion, scoord(m), image),
              label + " image region");
      } else {
        // Across slices a 2D region has no one image: the images of its points instead
        // (TID 320 row 1). SCOORD3D would fit, but DCMTK's TID 300 class has no call for it.
        for (int t : touched)
          check(value.addImage(
                    CODE_DCM_SourceOfMeasurement,
                    DSRImageReferenceValue(s.sopClassUid, s.sliceSopInstanceUids[size_t(t)])),
                label + " image");
      }
    };
    const DSRCodedEntryValue mm("mm", "UCUM", "millimeter");
    if (m.kind == ReportKind::Length) {
      if (m.value) add(DSRCodedEntryValue("410668003", "SCT", "Length"), *m.value, mm, nullptr);
    } else if (m.kind == ReportKind::Angle) {
      if (m.value)
        add(DSRCodedEntryValue(CODE_DCM_Angle), *m.value,
            DSRCodedEntryValue("deg", "UCUM", "degree"), nullptr);
    } else {
      auto scaled = [&](double x) { return v.suv ? v.suv->toSuv(x) : x; };
      const CMR_CID7464 mean(CMR_CID7464::Mean), sd(CMR_CID7464::StandardDeviation),
          min(CMR_CID7464::Minimum), max(CMR_CID7464::Maximum);
      if (m.mean) add(roi.name, scaled(*m.mean), roi.unit, &mean);
      if (m.sd) add(roi.name, scaled(*m.sd), roi.unit, &sd);
      if (m.min) add(roi.name, scaled(*m.min), roi.unit, &min);
      if (m.max) add(roi.name, scaled(*m.max), roi.unit, &max);
      if (m.kind == ReportKind::Segment) {
        if (m.volumeMm3)
          add(DSRCodedEntryValue("118565006", "SCT", "Volume"), *m.volumeMm3,
              DSRCodedEntryValue("mm3", "UCUM", "cubic millimeter"), nullptr);
      } else {
        add(DSRCodedEntryValue("42798000", "SCT", "Area"), m.areaMm2,
            DSRCodedEntryValue("mm2", "UCUM", "square millimeter"), nullptr);
      }
      // SUVpeak (PERCIST's 1 cm³ sphere): SUVbw (126401, DCM) derived as the Peak Value
      // Within ROI (126031, DCM; CID 7464), in g/ml{SUVbw}. Already in SUVbw: it may be the
      // fused PET overlay's, whatever this volume's unit.
      if (m.suvPeak) {
        const CMR_CID7464 peak(CMR_CID7464::PeakValueWithinROI);
        add(DSRCodedEntryValue("126401", "DCM", "SUVbw"), *m.suvPeak,
            DSRCodedEntryValue("g/ml{SUVbw}", "UCUM", "Standardized Uptake Value body weight"),
            &peak);
      }
    }
    if (!group.hasMeasurements(OFTrue))
      throw inputError(label +
                       " has no value (an angle with a zero-length arm, or an ROI "
                       "without a pixel): leave it out of the report");
  }
  for (const std::string& comment : info.comments)
    check(report.addQualitativeEvaluation(DSRCodedEntryValue("121106", "DCM", "Comment"),
                                          OFString(comment.c_str())),
          "comment");
  if (!report.isValid())
    throw outputError("The measurement report is incomplete (TID 1500); please report this");

  DSRDocument doc(DSRTypes::DT_ComprehensiveSR);
  check(doc.setTreeFromRootTemplate(report, OFTrue), "document tree");
  report::fileWithImages(doc, s, "9001", info.seriesDescription, check);
  // Complete: every measurement made is in it; unverified: a person has not signed it.
  doc.completeDocument();
  // Every image the tree references is evidence of this study.
  report::addEvidence(doc, s, slices, check);
  DcmFileFormat file;
  check(doc.write(*file.getDataset()), "DICOM dataset");
  OFString uid;
  doc.getSOPInstanceUID(uid);
  out.sopInstanceUid = uid.c_str();
  dicomwrite::saveAtomically(file, path, "measurement report");
  return out;
}

}  // namespace voxray
