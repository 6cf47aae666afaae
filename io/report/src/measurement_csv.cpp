#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "voxray/io/error.h"
#include "voxray/io/measurement_report.h"

namespace voxray {

int measurementSlice(const ReportMeasurement& m) {
  if (m.points.empty()) return -1;
  const bool roi = m.kind == ReportKind::Ellipse || m.kind == ReportKind::Rect;
  // An ROI lies in the slice of its first corner along its normal (engine/measure.h).
  if (roi) return m.normalAxis == 2 ? int(std::lround(m.points[0].z)) : -1;
  if (m.in3d) return -1;  // picked in the 3D view: on no slice, wherever its points lie
  for (const auto& p : m.points)
    if (std::abs(p.z - m.points[0].z) > 1e-6) return -1;
  return int(std::lround(m.points[0].z));
}

namespace {

std::string number(double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string kindName(ReportKind k) {
  switch (k) {
    case ReportKind::Length:
      return "length";
    case ReportKind::Angle:
      return "angle";
    case ReportKind::Ellipse:
      return "ellipse";
    case ReportKind::Rect:
      return "rect";
    case ReportKind::Segment:
      return "segment";
  }
  return "";
}

// Quotes a CSV field (RFC 4180) when it needs it: labels are the user's text.
std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

void writeMeasurementCsv(const std::string& path, const Volume& v,
                         const std::vector<ReportMeasurement>& measurements) {
  std::ostringstream out;
  out << "label,kind,quantity,value,unit,slice,points_voxel,points_lps_mm\n";
  const bool suv = bool(v.suv);
  const std::string unit = suv ? v.suv->unit : v.unit;
  for (const auto& m : measurements) {
    std::string vox, mm;
    for (const auto& p : m.points) {
      const glm::dvec3 q = v.originMm + v.direction * (p * v.spacingMm);
      vox += (vox.empty() ? "" : " ") + number(p.x) + ":" + number(p.y) + ":" + number(p.z);
      mm += (mm.empty() ? "" : " ") + number(q.x) + ":" + number(q.y) + ":" + number(q.z);
    }
    const int slice = measurementSlice(m);
    auto row = [&](const char* quantity, const std::optional<double>& x, const std::string& u) {
      out << field(m.label) << "," << kindName(m.kind) << "," << quantity << ","
          << (x ? number(*x) : "") << "," << u << "," << (slice >= 0 ? std::to_string(slice) : "")
          << "," << vox << "," << mm << "\n";
    };
    auto scaled = [&](const std::optional<double>& x) -> std::optional<double> {
      if (!x || !suv) return x;
      return v.suv->toSuv(*x);
    };
    if (m.kind == ReportKind::Length) row("length", m.value, "mm");
    if (m.kind == ReportKind::Angle) row("angle", m.value, "deg");
    if (m.kind == ReportKind::Ellipse || m.kind == ReportKind::Rect) {
      row("mean", scaled(m.mean), unit);
      row("sd", scaled(m.sd), unit);
      row("min", scaled(m.min), unit);
      row("max", scaled(m.max), unit);
      row("area", m.areaMm2, "mm2");
      row("pixels", double(m.pixels), "");
    }
    if (m.kind == ReportKind::Segment) {
      row("mean", scaled(m.mean), unit);
      row("sd", scaled(m.sd), unit);
      row("min", scaled(m.min), unit);
      row("max", scaled(m.max), unit);
      row("volume", m.volumeMm3, "mm3");
    }
    if (m.suvPeak) row("suv_peak", m.suvPeak, "SUVbw");
  }
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << out.str();
  if (!file.flush())
    throw outputError("Cannot write the measurements CSV " + path +
                      ": check the folder exists and has free space");
}

}  // namespace voxray
