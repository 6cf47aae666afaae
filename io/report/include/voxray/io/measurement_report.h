#pragma once
// Measurements leave Voxray as CSV and as a DICOM SR (TID 1500 Measurement Report). The
// values are the engine's (voxray/engine/measure.h); these plain structs carry them to io,
// which knows no engine.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/volume.h"

namespace voxray {

// Segment: a 3D region of the segment editor (its statistics, no points).
enum class ReportKind { Length, Angle, Ellipse, Rect, Segment };

struct ReportMeasurement {
  ReportKind kind = ReportKind::Length;
  std::string label;  // the tracking identifier, e.g. "line 1"; never patient text
  // Voxel positions (i, j, k) of the volume: a line's 2 ends, an angle's 3 points (vertex in
  // the middle), an ROI's 2 opposite corners of its bounding box.
  std::vector<glm::dvec3> points;
  int normalAxis = 2;           // ROI: the voxel axis across its plane (0 = i, 1 = j, 2 = k)
  std::optional<double> value;  // length (mm) or angle (degrees); none: no value (zero arm)
  // ROI statistics in the volume's unit (HU, or as stored); the report converts to SUVbw
  // itself when the volume has an SUV scale.
  std::optional<double> mean, sd, min, max;
  double areaMm2 = 0.0;
  size_t pixels = 0;
  // A segment: its volume, and its SUVpeak already in SUVbw (the volume's SUV or the fused PET
  // overlay's; segment_peak.h). ROIs may carry an SUVpeak too.
  std::optional<double> volumeMm3, suvPeak;
  // A segment: its number in the DICOM SEG written from the same segmentation (1 = its first
  // segment; 0 = none), and its centroid, the mean of its voxels' positions (voxels i, j, k).
  int segmentNumber = 0;
  std::optional<glm::dvec3> centroid;
  // Made in the 3D view: reported in patient coordinates (SCOORD3D, LPS mm, in the volume's
  // Frame of Reference) as are measurements whose points lie off one image (turned planes).
  bool in3d = false;
};

// The slice a measurement lies on when all its points share one k (the image of a source
// file); -1 when they do not (an oblique line, an ROI across i or j).
int measurementSlice(const ReportMeasurement& m);

struct MeasurementReportInfo {
  std::string seriesDescription = "Voxray measurements";
  // Free text for the whole report (the workstation's text and arrow annotations): each one a
  // TEXT content item, TID 1500's qualitative evaluation in text form (row 14), named
  // (121106, DCM, "Comment").
  std::vector<std::string> comments;
  // The DICOM SEG (Segmentation Storage) holding the segments, its SOP Instance and Series
  // Instance UID as writeDicomSeg returned them (the report lists it as evidence); empty: none
  // was written, and segment groups say so.
  std::string segSopInstanceUid, segSeriesInstanceUid;
};

struct WrittenReport {
  std::string sopInstanceUid;
  std::vector<std::string> notes;  // what the user should know (series-only references, ...)
};

// Writes MEASUREMENTS of V as a Comprehensive SR following TID 1500 into PATH, in V's study.
// Each measurement is a TID 1501 group (tracking identifier, TID 300 values with units in
// UCUM) that references the source image of its slice (SOP Instance UID from
// v.study.sliceSopInstanceUids) with its SCOORD in that image's pixels; without per-slice
// UIDs it references the series only and says so in the notes. A measurement off one image
// (in3d, or points on several slices) has its points as SCOORD3D in LPS mm with the volume's
// Frame of Reference UID, and the document is then a Comprehensive 3D SR. A segment's group
// holds its statistics, volume and SUVpeak (SUVbw, derivation Peak Value Within ROI); with
// info.segSopInstanceUid it is a TID 1411 Volumetric ROI group that references its segment in
// that SEG (Referenced Segment, 121191 DCM) and the segmented series (Source series for
// segmentation, 121232 DCM), its centroid a SCOORD3D POINT under its volume. Throws Error
// (Input) for a volume not read from DICOM or no measurements, (Output) when PATH cannot be
// written.
WrittenReport writeMeasurementReport(const std::string& path, const Volume& v,
                                     const std::vector<ReportMeasurement>& measurements,
                                     const MeasurementReportInfo& info = {});

// One row per value: label, kind, quantity, value, unit, slice, points (voxels and LPS mm).
// Throws Error (Output) when PATH cannot be written.
void writeMeasurementCsv(const std::string& path, const Volume& v,
                         const std::vector<ReportMeasurement>& measurements);

}  // namespace voxray
