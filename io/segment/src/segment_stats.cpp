#include "voxray/io/segment_stats.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"
#include "voxray/io/segmentation_check.h"

namespace voxray {

SegmentStats segmentStats(const Segmentation& s, const Volume& v, uint8_t label) {
  checkSegmentation(s);
  checkSameGrid(s, v);
  SegmentStats out;
  out.label = label;
  out.unit = v.unit;
  if (const Segment* seg = s.find(label)) out.name = seg->name;
  // A histogram of the stored values gives the exact median in one pass over the voxels.
  std::vector<uint64_t> histogram(65536, 0);
  double sum = 0.0, sum2 = 0.0;
  for (size_t i = 0; i < s.labels.size(); ++i) {
    if (s.labels[i] != label) continue;
    const int16_t stored = v.voxels[i];
    ++histogram[size_t(int(stored) + 32768)];
    const double x = v.toPhysical(stored);
    sum += x;
    sum2 += x * x;
    ++out.voxels;
  }
  out.volumeMm3 = double(out.voxels) * s.grid.voxelVolumeMm3();
  out.volumeMl = out.volumeMm3 / 1000.0;
  if (out.voxels == 0) return out;
  const double n = double(out.voxels);
  out.mean = sum / n;
  // The population SD, as the workstation's ROI statistics.
  out.sd = std::sqrt(std::max(0.0, sum2 / n - *out.mean * *out.mean));
  int first = 0, last = 65535;
  while (!histogram[size_t(first)]) ++first;
  while (!histogram[size_t(last)]) --last;
  double a = v.toPhysical(first - 32768), b = v.toPhysical(last - 32768);
  out.min = std::min(a, b);
  out.max = std::max(a, b);
  // The median of an even count is the mean of the two middle values.
  auto valueAt = [&](uint64_t rank) {
    uint64_t seen = 0;
    for (int h = first; h <= last; ++h) {
      seen += histogram[size_t(h)];
      if (seen > rank) return v.toPhysical(h - 32768);
    }
    return v.toPhysical(last - 32768);
  };
  const uint64_t count = out.voxels;
  out.median = count % 2 ? valueAt(count / 2) : (valueAt(count / 2 - 1) + valueAt(count / 2)) / 2;
  return out;
}

std::vector<SegmentStats> allSegmentStats(const Segmentation& s, const Volume& v) {
  std::vector<SegmentStats> out;
  for (const auto& seg : s.segments) out.push_back(segmentStats(s, v, seg.label));
  return out;
}

namespace {

std::string number(const std::optional<double>& x) {
  if (!x) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", *x);
  return buf;
}

// CSV: a name with a comma, quote or line break goes in quotes, quotes doubled.
std::string csvText(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

nlohmann::json optionalJson(const std::optional<double>& x) {
  return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
}

}  // namespace

std::string statsCsv(const std::vector<SegmentStats>& stats) {
  std::ostringstream out;
  out << "label,name,voxels,volume_mm3,volume_ml,unit,mean,sd,min,max,median,surface_mm2,"
         "suv_peak\n";
  for (const auto& s : stats)
    out << int(s.label) << "," << csvText(s.name) << "," << s.voxels << "," << number(s.volumeMm3)
        << "," << number(s.volumeMl) << "," << csvText(s.unit) << "," << number(s.mean) << ","
        << number(s.sd) << "," << number(s.min) << "," << number(s.max) << "," << number(s.median)
        << "," << number(s.surfaceMm2) << "," << number(s.suvPeak) << "\n";
  return out.str();
}

std::string statsJson(const std::vector<SegmentStats>& stats) {
  nlohmann::json segments = nlohmann::json::array();
  for (const auto& s : stats) {
    segments.push_back({{"label", s.label},
                        {"name", s.name},
                        {"voxels", s.voxels},
                        {"volume_mm3", s.volumeMm3},
                        {"volume_ml", s.volumeMl},
                        {"unit", s.unit},
                        {"mean", optionalJson(s.mean)},
                        {"sd", optionalJson(s.sd)},
                        {"min", optionalJson(s.min)},
                        {"max", optionalJson(s.max)},
                        {"median", optionalJson(s.median)},
                        {"surface_mm2", optionalJson(s.surfaceMm2)},
                        {"suv_peak", optionalJson(s.suvPeak)}});
    if (!s.peakOf.empty()) segments.back()["suv_peak_of"] = s.peakOf;
    if (!s.peakNote.empty()) segments.back()["suv_peak_note"] = s.peakNote;
  }
  // Names are the user's text: dump replaces invalid UTF-8 rather than throwing.
  return nlohmann::json{{"segments", segments}}.dump(2, ' ', false,
                                                     nlohmann::json::error_handler_t::replace) +
         "\n";
}

}  // namespace voxray
