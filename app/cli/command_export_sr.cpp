// voxray-cli export-sr: measurements (measure's flags, each repeatable) as a DICOM SR
// (TID 1500) and/or CSV. The values are the engine's, as measure prints them.
#include <iostream>

#include "commands.h"
#include "existing_output.h"
#include "input_options.h"
#include "labels_option.h"
#include "measure_points.h"
#include "results_export.h"
#include "voxray/engine/measure.h"
#include "voxray/io/error.h"
#include "voxray/io/measurement_report.h"
#include "voxray/io/segment_files.h"

namespace voxray::cli {

namespace {

struct ExportSrOptions {
  std::vector<std::string> lines, angles, ellipses, rects;
  std::string plane = "k";
  std::string output, csv;
  std::string seg;      // --seg FILE: the segments as a DICOM SEG the report's groups reference
  LabelsOption labels;  // segments: --labels FILE or --labels-raw FILE on the volume's grid
  bool mm = false, force = false;
};

std::vector<ReportMeasurement> measurements(const Volume& v, const ExportSrOptions& o) {
  std::vector<ReportMeasurement> out;
  auto points = [&](const std::string& text, size_t count, const char* flag) {
    auto p = parsePoints(text, count, flag);
    if (o.mm)
      for (auto& q : p) q = patientToVoxel(v, q);
    return p;
  };
  int n = 0;
  for (const auto& t : o.lines) {
    ReportMeasurement m;
    m.kind = ReportKind::Length;
    m.label = "line " + std::to_string(++n);
    m.points = points(t, 2, "--line");
    m.value = distanceMm(v, m.points[0], m.points[1]);
    out.push_back(m);
  }
  n = 0;
  for (const auto& t : o.angles) {
    ReportMeasurement m;
    m.kind = ReportKind::Angle;
    m.label = "angle " + std::to_string(++n);
    m.points = points(t, 3, "--angle");
    m.value = angleDeg(v, m.points[0], m.points[1], m.points[2]);
    out.push_back(m);
  }
  auto roi = [&](const std::vector<std::string>& list, RoiShape shape, const char* name,
                 const char* flag) {
    int k = 0;
    for (const auto& t : list) {
      ReportMeasurement m;
      m.kind = shape == RoiShape::Rect ? ReportKind::Rect : ReportKind::Ellipse;
      m.label = std::string(name) + " " + std::to_string(++k);
      m.points = points(t, 2, flag);
      m.normalAxis = planeAxis(o.plane);
      const RoiStats s = roiStats(v, PlaneRoi{shape, m.normalAxis, m.points[0], m.points[1]});
      m.mean = s.mean, m.sd = s.sd, m.min = s.min, m.max = s.max;
      m.areaMm2 = s.areaMm2;
      m.pixels = s.pixels;
      out.push_back(m);
    }
  };
  roi(o.ellipses, RoiShape::Ellipse, "ellipse", "--ellipse");
  roi(o.rects, RoiShape::Rect, "rect", "--rect");
  return out;
}

int runExportSr(const InputOptions& in, const ExportSrOptions& o) {
  if (o.output.empty() && o.csv.empty())
    throw inputError("export-sr: give -o REPORT.dcm (DICOM SR), --csv FILE, or both");
  if (o.lines.empty() && o.angles.empty() && o.ellipses.empty() && o.rects.empty() &&
      o.labels.file.empty() && o.labels.raw.empty())
    throw inputError("export-sr: give at least one --line, --angle, --ellipse, --rect or --labels");
  refuseExisting(o.output, o.force);
  refuseExisting(o.csv, o.force);
  refuseExisting(o.seg, o.force);
  if (!o.seg.empty() && o.labels.file.empty() && o.labels.raw.empty())
    throw inputError(
        "export-sr: --seg writes the segments of --labels as a DICOM SEG: give --labels too");
  const Volume v = in.load();
  auto list = measurements(v, o);
  MeasurementReportInfo info;
  if (const auto segmentation = o.labels.load(v)) {
    // Each segment's statistics, volume and SUVpeak (a PET with its SUV attributes).
    const auto segments = reportSegments(*segmentation, v);
    list.insert(list.end(), segments.begin(), segments.end());
    if (!o.seg.empty()) {
#ifdef VOXRAY_HAS_SEGMENT_FILES
      // Written first: the report's segment groups reference it by its SOP Instance UID.
      DicomSegOptions segOptions;
      segOptions.force = o.force;
      const WrittenDicomSeg written = writeDicomSeg(o.seg, *segmentation, v.study, segOptions);
      info.segSopInstanceUid = written.sopInstanceUid;
      info.segSeriesInstanceUid = written.seriesInstanceUid;
      std::cout << o.seg << ": DICOM SEG of " << segmentation->segments.size() << " segment"
                << (segmentation->segments.size() == 1 ? "" : "s") << ", SOP Instance UID "
                << info.segSopInstanceUid << "\n";
#else
      throw inputError(
          "export-sr --seg: this build has no DICOM SEG writer (built without "
          "DCMTK); use a full build");
#endif
    }
  }
  if (!o.output.empty()) {
    const WrittenReport r = writeMeasurementReport(o.output, v, list, info);
    std::cout << o.output << ": measurement report (TID 1500) with " << list.size()
              << " measurement" << (list.size() == 1 ? "" : "s") << ", SOP Instance UID "
              << r.sopInstanceUid << "\n";
    for (const auto& note : r.notes) std::cout << "note: " << note << "\n";
  }
  if (!o.csv.empty()) {
    writeMeasurementCsv(o.csv, v, list);
    std::cout << o.csv << ": " << list.size() << " measurement" << (list.size() == 1 ? "" : "s")
              << " as CSV\n";
  }
  return 0;
}

}  // namespace

Run addExportSrCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export-sr",
      "Measurements as a DICOM SR (TID 1500 measurement report) and/or CSV, with their images");
  auto in = std::make_shared<InputOptions>();
  auto o = std::make_shared<ExportSrOptions>();
  in->add(*cmd);
  cmd->add_option("--line", o->lines,
                  "a distance between P1,P2 (points I:J:K in voxels); repeatable");
  cmd->add_option("--angle", o->angles, "an angle at P2 between P1 and P3; repeatable");
  cmd->add_option("--ellipse", o->ellipses, "an ellipse ROI in the corners P1,P2; repeatable");
  cmd->add_option("--rect", o->rects, "a rectangle ROI in the corners P1,P2; repeatable");
  cmd->add_option("--plane", o->plane,
                  "the voxel axis across the ROIs' plane: i, j or k (default k)");
  o->labels.add(*cmd);  // each segment's statistics, volume and SUVpeak (PET) as a group
  cmd->add_flag("--mm", o->mm, "points are LPS patient positions in mm, not voxel indices");
  cmd->add_option("-o,--output", o->output, "the DICOM SR file to write");
  cmd->add_option("--csv", o->csv, "also (or only) write the values as CSV");
  cmd->add_option("--seg", o->seg,
                  "also write the --labels segments as this DICOM SEG; the report's segment "
                  "groups (TID 1411) reference it");
  cmd->add_flag("--force", o->force, "overwrite existing output files");
  return [in, o] { return runExportSr(*in, *o); };
}

}  // namespace voxray::cli
