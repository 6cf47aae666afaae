#include "results_export.h"

#include <algorithm>
#include <filesystem>

#include "segment_peak.h"
#include "voxray/engine/measure.h"
#include "voxray/io/error.h"

namespace voxray {

namespace fs = std::filesystem;

std::vector<ReportMeasurement> reportMeasurements(const Volume& v, const MeasurementModel& m) {
  std::vector<ReportMeasurement> out;
  int lines = 0, angles = 0, ellipses = 0, rects = 0;
  for (const Measurement& x : m.items()) {
    ReportMeasurement r;
    r.points = x.points;
    r.normalAxis = x.normalAxis < 0 ? 2 : x.normalAxis;
    r.in3d = x.normalAxis < 0;  // picked on surfaces in the 3D view
    switch (x.kind) {
      case MeasureKind::Distance:
        r.kind = ReportKind::Length;
        r.label = "line " + std::to_string(++lines);
        r.value = distanceMm(v, x.points[0], x.points[1]);
        break;
      case MeasureKind::Angle:
        r.kind = ReportKind::Angle;
        r.label = "angle " + std::to_string(++angles);
        r.value = angleDeg(v, x.points[0], x.points[1], x.points[2]);
        break;
      case MeasureKind::Ellipse:
      case MeasureKind::Rect: {
        const bool ellipse = x.kind == MeasureKind::Ellipse;
        r.kind = ellipse ? ReportKind::Ellipse : ReportKind::Rect;
        r.label =
            ellipse ? "ellipse " + std::to_string(++ellipses) : "rect " + std::to_string(++rects);
        const RoiStats s = measurementStats(v, x);
        r.mean = s.mean, r.sd = s.sd, r.min = s.min, r.max = s.max;
        r.areaMm2 = s.areaMm2;
        r.pixels = s.pixels;
        break;
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<ReportMeasurement> reportSegments(const Segmentation& s, const Volume& v,
                                              const Volume* overlay,
                                              const std::string& overlayName) {
  std::vector<SegmentStats> stats = allSegmentStats(s, v);
  addSuvPeaks(stats, s, v, overlay, overlayName);
  // Each label's centroid: the mean of its voxels' indices (one pass over the label map).
  std::vector<glm::dvec3> sum(256, glm::dvec3(0.0));
  std::vector<size_t> count(256, 0);
  const glm::ivec3 d = s.grid.dims;
  size_t n = 0;
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i, ++n) {
        const uint8_t l = n < s.labels.size() ? s.labels[n] : 0;
        if (l == 0) continue;
        sum[l] += glm::dvec3(i, j, k);
        ++count[l];
      }
  std::vector<ReportMeasurement> out;
  for (const SegmentStats& st : stats) {
    if (st.voxels == 0) continue;  // nothing to report of an empty segment
    ReportMeasurement r;
    // The DICOM SEG numbers segments in the segmentation's order (writeDicomSeg).
    for (size_t x = 0; x < s.segments.size(); ++x)
      if (s.segments[x].label == st.label) r.segmentNumber = int(x) + 1;
    if (count[st.label] > 0) r.centroid = sum[st.label] / double(count[st.label]);
    r.kind = ReportKind::Segment;
    r.label = "segment " + std::to_string(int(st.label)) + (st.name.empty() ? "" : " " + st.name);
    r.mean = st.mean, r.sd = st.sd, r.min = st.min, r.max = st.max;
    r.volumeMm3 = st.volumeMm3;
    r.suvPeak = st.suvPeak;
    r.pixels = st.voxels;
    out.push_back(std::move(r));
  }
  return out;
}

bool KeyImageSet::contains(int k) const {
  return std::find(slices_.begin(), slices_.end(), k) != slices_.end();
}

bool KeyImageSet::toggle(int k) {
  auto it = std::find(slices_.begin(), slices_.end(), k);
  const bool marked = it == slices_.end();
  if (marked)
    slices_.push_back(k);
  else
    slices_.erase(it);
  changed.notify();
  return marked;
}

void KeyImageSet::clear() {
  if (slices_.empty()) return;
  slices_.clear();
  changed.notify();
}

namespace {
fs::path normal(const std::string& p) {
  std::error_code ec;
  fs::path abs = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return abs.lexically_normal();
}
}  // namespace

bool insideFolder(const std::string& path, const std::string& folder) {
  if (path.empty() || folder.empty()) return false;
  std::string p = normal(path).string(), f = normal(folder).string();
  while (f.size() > 1 && f.back() == '/') f.pop_back();
  return p == f || (p.size() > f.size() && p.compare(0, f.size(), f) == 0 &&
                    (f == "/" || p[f.size()] == '/'));
}

std::string sourceFolder(const std::string& input) {
  if (input.empty()) return "";
  std::error_code ec;
  if (fs::is_directory(input, ec)) return input;
  return fs::path(input).parent_path().string();
}

void refuseSourceFolder(const std::string& path, const std::string& input) {
  const std::string folder = sourceFolder(input);
  if (insideFolder(path, folder))
    throw outputError(path + " lies in the folder the study was read from (" + folder +
                      "); results never go into the data's folder: choose another one");
}

}  // namespace voxray
