// The TID 1500 Measurement Report through DCMTK's template classes (dcmsr/cmr): they add the
// content items in the template's order with its relationships, and check each value.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

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
using VolumeGroup = CMR_TID1411_in_TID1500;
using Value = Group::MeasurementValue;

void checkSrStep(const OFCondition& c, const std::string& what) {
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

glm::dvec3 patientMm(const Volume& v, const glm::dvec3& voxel) {
  return v.originMm + v.direction * (voxel * v.spacingMm);
}

// Whether M goes in patient coordinates (SCOORD3D): made in the 3D view, or its points off
// one image (an oblique line, an ROI in a coronal or sagittal plane).
bool in3d(const ReportMeasurement& m) {
  return m.kind != ReportKind::Segment && !m.points.empty() && (m.in3d || measurementSlice(m) < 0);
}

// M's points as SCOORD3D in LPS mm (PS3.3 C.18.9.1.2): a line or an angle's arms as a
// POLYLINE, a rectangle as a closed POLYGON (first point repeated last), an ellipse as its
// major and then minor axis' ends in its plane (the two voxel axes other than its normal).
DSRSpatialCoordinates3DValue scoord3d(const Volume& v, const ReportMeasurement& m) {
  auto add = [&](DSRSpatialCoordinates3DValue& s, const glm::dvec3& voxel) {
    const glm::dvec3 p = patientMm(v, voxel);
    s.getGraphicDataList().addItem(Float32(p.x), Float32(p.y), Float32(p.z));
  };
  if (m.kind == ReportKind::Length || m.kind == ReportKind::Angle) {
    DSRSpatialCoordinates3DValue s(DSRTypes::GT3_Polyline);
    for (const auto& p : m.points) add(s, p);
    return s;
  }
  const glm::dvec3 &a = m.points[0], &b = m.points[1];
  // The plane's two axes: u and w, the voxel axes other than the normal.
  const int n = m.normalAxis < 0 || m.normalAxis > 2 ? 2 : m.normalAxis;
  const int u = n == 0 ? 1 : 0, w = n == 2 ? 1 : 2;
  auto at = [&](double cu, double cw) {
    glm::dvec3 p = a;
    p[u] = cu;
    p[w] = cw;
    return p;
  };
  if (m.kind == ReportKind::Rect) {
    DSRSpatialCoordinates3DValue s(DSRTypes::GT3_Polygon);
    const double us[] = {a[u], b[u], b[u], a[u], a[u]}, ws[] = {a[w], a[w], b[w], b[w], a[w]};
    for (int k = 0; k < 5; ++k) add(s, at(us[k], ws[k]));
    return s;
  }
  DSRSpatialCoordinates3DValue s(DSRTypes::GT3_Ellipse);
  const double cu = (a[u] + b[u]) / 2, cw = (a[w] + b[w]) / 2;
  // The axes in mm decide which is major (the voxels need not be square).
  const double ru = std::abs(b[u] - a[u]) / 2, rw = std::abs(b[w] - a[w]) / 2;
  if (ru * v.spacingMm[u] >= rw * v.spacingMm[w]) {
    add(s, at(cu - ru, cw)), add(s, at(cu + ru, cw)), add(s, at(cu, cw - rw)),
        add(s, at(cu, cw + rw));
  } else {
    add(s, at(cu, cw - rw)), add(s, at(cu, cw + rw)), add(s, at(cu - ru, cw)),
        add(s, at(cu + ru, cw));
  }
  return s;
}

// Adds M's SCOORD3D under each of its values (TID 300 row 8 → TID 320 row 5: INFERRED FROM
// SCOORD3D "Source of Measurement" with the Frame of Reference), or only under the values named
// ONLY: DCMTK's TID 300 class has no call for it, so it goes into the finished tree, found by
// the group's tracking identifier.
void addScoord3d(DSRDocumentTree& tree, const std::string& label,
                 const DSRSpatialCoordinates3DValue& coordinates,
                 const DSRCodedEntryValue* only = nullptr) {
  const DSRCodedEntryValue trackingId(CODE_DCM_TrackingIdentifier);
  std::vector<size_t> values;  // the node IDs of the group's NUM items
  bool inGroup = false;
  if (tree.gotoRoot() == 0) return;
  do {
    const DSRContentItem& item = tree.getCurrentContentItem();
    if (item.getValueType() == DSRTypes::VT_Text && item.getConceptName() == trackingId)
      inGroup = item.getStringValue() == label.c_str();
    else if (inGroup && item.getValueType() == DSRTypes::VT_Num &&
             (!only || item.getConceptName() == *only))
      values.push_back(tree.getNodeID());
  } while (tree.iterate());
  if (values.empty()) checkSrStep(EC_IllegalCall, label + " (no value to give 3D coordinates)");
  for (size_t id : values) {
    if (tree.gotoNode(id) == 0) checkSrStep(EC_IllegalCall, label + " (its value is lost)");
    if (tree.addContentItem(DSRTypes::RT_inferredFrom, DSRTypes::VT_SCoord3D,
                            DSRTypes::AM_belowCurrent) == 0)
      checkSrStep(EC_IllegalCall, label + " 3D coordinates");
    checkSrStep(tree.getCurrentContentItem().setConceptName(CODE_DCM_SourceOfMeasurement),
                label + " 3D coordinates' name");
    checkSrStep(tree.getCurrentContentItem().setSpatialCoordinates3D(coordinates),
                label + " 3D coordinates");
  }
}

// A segment's volume: the value its centroid goes under.
const DSRCodedEntryValue& volumeConcept() {
  static const DSRCodedEntryValue volume("118565006", "SCT", "Volume");
  return volume;
}

struct Coordinates3d {
  std::string label;
  DSRSpatialCoordinates3DValue value;
  bool underVolumeOnly = false;  // a segment's centroid: under its volume, not its HU values
};

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
  checkSrStep(report.setLanguage(CID5000_Languages::English, CID5001_Countries::UnitedStates),
              "language");
  checkSrStep(report.getObservationContext().addDeviceObserver(
                  dicomwrite::newUid(SITE_INSTANCE_UID_ROOT), "Voxray", "Voxray"),
              "observer");
  checkSrStep(
      report.addProcedureReported(CMR_CID100(DSRCodedEntryValue(CODE_SCT_ImagingProcedure))),
      "procedure");
  // The image library lists every image a measurement references, once.
  std::vector<int> slices;
  for (const auto& m : measurements)
    for (int k : touchedSlices(v, m))
      if (std::find(slices.begin(), slices.end(), k) == slices.end()) slices.push_back(k);
  checkSrStep(report.getImageLibrary().createNewImageLibrary(), "image library");
  if (!slices.empty()) checkSrStep(report.getImageLibrary().addImageGroup(), "image library group");
  for (int k : slices) {
    DcmItem image;
    image.putAndInsertString(DCM_SOPClassUID, s.sopClassUid.c_str());
    image.putAndInsertString(DCM_SOPInstanceUID, s.sliceSopInstanceUids[size_t(k)].c_str());
    checkSrStep(
        report.getImageLibrary().addImageEntry(image, TID1600_ImageLibrary::withoutDescriptors),
        "image library entry");
  }

  const Quantity roi = roiQuantity(v);
  const std::string& frameOfReference = s.frameOfReferenceUid;
  // Measurements off one image go in patient coordinates: SCOORD3D needs the Comprehensive 3D
  // SR (the Comprehensive SR IOD has no SCOORD3D) and the volume's Frame of Reference.
  std::vector<Coordinates3d> points3d;
  int number = 0;
  for (const auto& m : measurements) {
    ++number;
    const std::string label = m.label.empty() ? "measurement " + std::to_string(number) : m.label;
    const int k = measurementSlice(m);
    const bool onImage = perSlice && k >= 0 && k < v.dims.z;
    const std::vector<int> touched = touchedSlices(v, m);
    const bool coordinates3d = in3d(m) && !frameOfReference.empty();
    // A segment written as a DICOM SEG with the report: a TID 1411 group naming it there.
    const bool volumetric = m.kind == ReportKind::Segment && m.segmentNumber > 0 &&
                            !info.segSopInstanceUid.empty() && !s.seriesInstanceUid.empty();
    if (volumetric)
      out.notes.push_back(label + ": references segment " + std::to_string(m.segmentNumber) +
                          " of the DICOM SEG " + info.segSopInstanceUid);
    else if (m.kind == ReportKind::Segment)
      out.notes.push_back(label +
                          ": a segment's values reference the series, not its images; no DICOM "
                          "SEG was written with the report, so the group names no segment");
    else if (coordinates3d)
      out.notes.push_back(label +
                          ": off one image (3D view or a turned plane); its points are "
                          "given in patient coordinates (SCOORD3D, LPS mm)");
    else if (perSlice && !onImage)
      out.notes.push_back(label + ": its points lie on " + std::to_string(touched.size()) +
                          " slices; it references their images without image coordinates");
    Group* group = nullptr;
    VolumeGroup* volume = nullptr;
    if (volumetric) {
      // TID 1411 allows one reference to the region (rows 5 to 8: image regions, a volume
      // surface or the segment): the segment, since it has every voxel.
      checkSrStep(report.addVolumetricROIMeasurements(), "volumetric measurement group");
      volume = &report.getVolumetricROIMeasurements();
      checkSrStep(volume->setTrackingIdentifier(label), "tracking identifier");
      checkSrStep(volume->setTrackingUniqueIdentifier(dicomwrite::newUid(SITE_INSTANCE_UID_ROOT)),
                  "tracking UID");
      DSRImageReferenceValue segment(UID_SegmentationStorage, info.segSopInstanceUid.c_str());
      segment.getSegmentList().addItem(Uint16(m.segmentNumber));
      checkSrStep(volume->setReferencedSegment(segment), label + " referenced segment");
      checkSrStep(volume->setSourceSeriesForSegmentation(s.seriesInstanceUid),
                  label + " source series");
    } else {
      checkSrStep(report.addIndividualMeasurements(), "measurement group");
      group = &report.getIndividualMeasurements();
      checkSrStep(group->setTrackingIdentifier(label), "tracking identifier");
      checkSrStep(group->setTrackingUniqueIdentifier(dicomwrite::newUid(SITE_INSTANCE_UID_ROOT)),
                  "tracking UID");
    }
    // One TID 300 per value, each with the image region it was measured in.
    auto add = [&](const DSRCodedEntryValue& name, double x, const DSRCodedEntryValue& unit,
                   const CID7464_GeneralRegionOfInterestMeasurementModifiers* derivation) {
      if (volume) {  // TID 1419's values: the segment is their region
        checkSrStep(volume->addMeasurement(CMR_CID7469(name), Value(ds(x), CMR_CID7181(unit)),
                                           OFTrue, OFTrue),
                    label + " value");
        if (derivation)
          checkSrStep(volume->getMeasurement().setDerivation(*derivation), label + " derivation");
        return;
      }
      checkSrStep(
          group->addMeasurement(CMR_CID7469(name), Value(ds(x), CMR_CID7181(unit)), OFTrue, OFTrue),
          label + " value");
      auto& value = group->getMeasurement();
      if (derivation) checkSrStep(value.setDerivation(*derivation), label + " derivation");
      if (m.kind == ReportKind::Segment) {
        // A label map has no SCOORD: the values name the series (the evidence) only.
      } else if (onImage) {
        DSRImageReferenceValue image(s.sopClassUid, s.sliceSopInstanceUids[size_t(k)]);
        checkSrStep(value.addSpatialCoordinates(CODE_DCM_ImageRegion, scoord(m), image),
                    label + " image region");
      } else {
        // Across slices a 2D region has no one image: the images of its points instead
        // (TID 320 row 1). SCOORD3D would fit, but DCMTK's TID 300 class has no call for it.
        for (int t : touched)
          checkSrStep(value.addImage(
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
          add(volumeConcept(), *m.volumeMm3, DSRCodedEntryValue("mm3", "UCUM", "cubic millimeter"),
              nullptr);
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
    const bool hasValues =
        volume ? volume->hasMeasurements(OFTrue) : group->hasMeasurements(OFTrue);
    if (coordinates3d && hasValues)
      points3d.push_back({label, scoord3d(v, m)});
    else if (m.kind == ReportKind::Segment && m.centroid && m.volumeMm3 && hasValues &&
             !frameOfReference.empty()) {
      // The centroid as a SCOORD3D POINT in LPS mm: TID 1411 has no row for a point beside
      // its segment reference, so it goes where TID 1419 → TID 300 allows coordinates (row 8,
      // INFERRED FROM SCOORD3D), under the volume.
      DSRSpatialCoordinates3DValue point(DSRTypes::GT3_Point);
      const glm::dvec3 p = patientMm(v, *m.centroid);
      point.getGraphicDataList().addItem(Float32(p.x), Float32(p.y), Float32(p.z));
      points3d.push_back({label, point, true});
    } else if (in3d(m) && frameOfReference.empty())
      out.notes.push_back(label +
                          ": off one image, but the series names no Frame of Reference: no 3D "
                          "coordinates");
    if (!hasValues)
      throw inputError(label +
                       " has no value (an angle with a zero-length arm, or an ROI "
                       "without a pixel): leave it out of the report");
  }
  for (const std::string& comment : info.comments)
    checkSrStep(report.addQualitativeEvaluation(DSRCodedEntryValue("121106", "DCM", "Comment"),
                                                OFString(comment.c_str())),
                "comment");
  if (!report.isValid())
    throw outputError("The measurement report is incomplete (TID 1500); please report this");

  DSRDocument doc(DSRTypes::DT_ComprehensiveSR);
  checkSrStep(doc.setTreeFromRootTemplate(report, OFTrue), "document tree");
  // The template makes the document the simplest type its tree fits (an Enhanced SR):
  // SCOORD3D needs the Comprehensive 3D SR, asked for before the coordinates go in.
  if (!points3d.empty())
    checkSrStep(doc.changeDocumentType(DSRTypes::DT_Comprehensive3DSR), "Comprehensive 3D SR");
  for (const Coordinates3d& p : points3d) {
    DSRSpatialCoordinates3DValue c = p.value;
    checkSrStep(c.setFrameOfReferenceUID(frameOfReference.c_str()),
                p.label + " Frame of Reference");
    addScoord3d(doc.getTree(), p.label, c, p.underVolumeOnly ? &volumeConcept() : nullptr);
  }
  report::fileWithImages(doc, s, "9001", info.seriesDescription, checkSrStep);
  // Complete: every measurement made is in it; unverified: a person has not signed it.
  doc.completeDocument();
  // Every image the tree references is evidence of this study.
  report::addEvidence(doc, s, slices, checkSrStep);
  // The SEG its segment groups reference: evidence too (PS3.3 C.17.2.3), in the same study.
  if (std::any_of(measurements.begin(), measurements.end(),
                  [&](const ReportMeasurement& m) {
                    return m.kind == ReportKind::Segment && m.segmentNumber > 0;
                  }) &&
      !info.segSopInstanceUid.empty())
    checkSrStep(doc.getCurrentRequestedProcedureEvidence().addItem(
                    s.studyInstanceUid, info.segSeriesInstanceUid, UID_SegmentationStorage,
                    info.segSopInstanceUid),
                "the SEG as evidence");
  DcmFileFormat file;
  checkSrStep(doc.write(*file.getDataset()), "DICOM dataset");
  OFString uid;
  doc.getSOPInstanceUID(uid);
  out.sopInstanceUid = uid.c_str();
  dicomwrite::saveAtomically(file, path, "measurement report");
  return out;
}

}  // namespace voxray
