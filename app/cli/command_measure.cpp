// voxray-cli measure: the workstation's distance, angle and ROI numbers, headless. The maths
// is voxray/engine/measure.h, the same functions the GUI's tools call.
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.h"
#include "input_options.h"
#include "json_text.h"
#include "measure_points.h"
#include "voxray/engine/measure.h"
#include "voxray/engine/roi_peak.h"
#include "voxray/io/error.h"

namespace voxray::cli {

namespace {

struct MeasureOptions {
  std::string line, angle, roi, corners;
  std::string plane = "k";
  bool mm = false, json = false;
};

nlohmann::json optionalJson(const std::optional<double>& x) {
  return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
}

std::string optionalText(const std::optional<double>& x) {
  if (!x) return "—";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", *x);
  return buf;
}

int runMeasure(const InputOptions& in, const MeasureOptions& o) {
  const int chosen = int(!o.line.empty()) + int(!o.angle.empty()) + int(!o.roi.empty());
  if (chosen != 1) throw inputError("measure: give exactly one of --line, --angle or --roi");
  if (!o.roi.empty() && o.roi != "ellipse" && o.roi != "rect")
    throw inputError("--roi '" + o.roi + "': give ellipse or rect");
  if (!o.roi.empty() && o.corners.empty())
    throw inputError("--roi needs --corners P1,P2 (opposite corners of its bounding box)");
  const Volume v = in.load();
  const char* flag = !o.line.empty() ? "--line" : !o.angle.empty() ? "--angle" : "--corners";
  const std::string& text = !o.line.empty() ? o.line : !o.angle.empty() ? o.angle : o.corners;
  std::vector<glm::dvec3> points = parsePoints(text, o.angle.empty() ? 2 : 3, flag);
  if (o.mm)
    for (auto& p : points) p = patientToVoxel(v, p);

  nlohmann::json j;
  nlohmann::json voxels = nlohmann::json::array(), mm = nlohmann::json::array();
  bool outside = false;
  for (const auto& p : points) {
    const glm::dvec3 q = voxelToPatient(v, p);
    voxels.push_back({p.x, p.y, p.z});
    mm.push_back({q.x, q.y, q.z});
    outside = outside || !insideVolume(v, p);
  }
  j["points_voxel"] = voxels;
  j["points_lps_mm"] = mm;
  j["outside_volume"] = outside;
  std::ostringstream out;
  if (!o.line.empty()) {
    const double d = distanceMm(v, points[0], points[1]);
    j["kind"] = "distance";
    j["distance_mm"] = d;
    out << "distance " << optionalText(d) << " mm\n";
  } else if (!o.angle.empty()) {
    const auto a = angleDeg(v, points[0], points[1], points[2]);
    j["kind"] = "angle";
    j["angle_deg"] = optionalJson(a);
    out << "angle    " << optionalText(a) << " deg\n";
  } else {
    PlaneRoi roi{o.roi == "rect" ? RoiShape::Rect : RoiShape::Ellipse, planeAxis(o.plane),
                 points[0], points[1]};
    const RoiStats s = roiStats(v, roi);
    j["kind"] = o.roi;
    j["plane"] = o.plane;
    j["slice"] = int(std::lround(points[0][roi.normalAxis]));
    j["unit"] = v.unit;
    j["pixels"] = s.pixels;
    j["area_mm2"] = s.areaMm2;
    j["mean"] = optionalJson(s.mean);
    j["sd"] = optionalJson(s.sd);
    j["min"] = optionalJson(s.min);
    j["max"] = optionalJson(s.max);
    out << "mean     " << optionalText(s.mean) << " " << v.unit << "\n"
        << "sd       " << optionalText(s.sd) << " " << v.unit << "\n"
        << "min      " << optionalText(s.min) << " " << v.unit << "\n"
        << "max      " << optionalText(s.max) << " " << v.unit << "\n"
        << "area     " << optionalText(s.areaMm2) << " mm2\n"
        << "pixels   " << s.pixels << "\n";
    // PET: the same statistics in SUV (a linear scale: SD scales alike).
    if (v.suv) {
      auto suv = [&](const std::optional<double>& x) -> std::optional<double> {
        if (!x) return std::nullopt;
        return v.suv->toSuv(*x);
      };
      j["suv"] = {{"unit", v.suv->unit},
                  {"factor", v.suv->factor},
                  {"mean", optionalJson(suv(s.mean))},
                  {"sd", optionalJson(suv(s.sd))},
                  {"min", optionalJson(suv(s.min))},
                  {"max", optionalJson(suv(s.max))}};
      out << "SUVmean  " << optionalText(suv(s.mean)) << " " << v.suv->unit << "\n"
          << "SUVsd    " << optionalText(suv(s.sd)) << " " << v.suv->unit << "\n"
          << "SUVmin   " << optionalText(suv(s.min)) << " " << v.suv->unit << "\n"
          << "SUVmax   " << optionalText(suv(s.max)) << " " << v.suv->unit << "\n";
      // SUVpeak (PERCIST): the best 1 cm³ sphere centred in the ROI (rules: roi_peak.h).
      const RoiPeak peak = roiPeak(v, roi);
      j["suv"]["peak"] = optionalJson(suv(peak.mean));
      if (peak.mean) {
        j["suv"]["peak_centre_voxel"] = {peak.centre.x, peak.centre.y, peak.centre.z};
        out << "SUVpeak  " << optionalText(suv(peak.mean)) << " " << v.suv->unit
            << " (1 cm3 sphere at voxel " << peak.centre.x << ":" << peak.centre.y << ":"
            << peak.centre.z << ")\n";
      } else {
        j["suv"]["peak_note"] = kNoRoomForPeak;
        out << "SUVpeak  — (" << kNoRoomForPeak << ")\n";
      }
    }
  }
  if (o.json) {
    std::cout << jsonText(j) << "\n";
    return 0;
  }
  std::cout << out.str();
  if (outside) std::cout << "note: a point lies outside the volume\n";
  return 0;
}

}  // namespace

Run addMeasureCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "measure", "Distance (mm), angle (degrees) or ROI statistics, as the workstation's tools");
  auto in = std::make_shared<InputOptions>();
  auto o = std::make_shared<MeasureOptions>();
  in->add(*cmd);
  cmd->add_option("--line", o->line, "distance between P1,P2 (points I:J:K in voxels)");
  cmd->add_option("--angle", o->angle, "angle at P2 between P1 and P3 (degrees)");
  cmd->add_option("--roi", o->roi, "ellipse or rect: mean, SD, min, max, area, pixel count");
  cmd->add_option("--corners", o->corners, "the ROI's opposite corners P1,P2");
  cmd->add_option("--plane", o->plane,
                  "the voxel axis across the ROI's plane: i, j or k (default k, the slices)");
  cmd->add_flag("--mm", o->mm, "points are LPS patient positions in mm, not voxel indices");
  cmd->add_flag("--json", o->json, "machine-readable output on stdout");
  return [in, o] { return runMeasure(*in, *o); };
}

}  // namespace voxray::cli
