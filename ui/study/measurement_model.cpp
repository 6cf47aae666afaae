#include "measurement_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "value_look.h"
#include "voxray/engine/roi_peak.h"
#include "voxray/io/volume.h"

namespace voxray {

const char* toString(MeasureKind k) {
  // In MeasureKind's order: the names the session file and the panel use.
  static const char* const kNames[] = {"distance", "angle", "ellipse", "rect"};
  const auto i = size_t(k);
  return i < std::size(kNames) ? kNames[i] : "?";
}

int pointCount(MeasureKind k) { return k == MeasureKind::Angle ? 3 : 2; }

const Measurement* MeasurementModel::find(int id) const {
  auto it = std::find_if(items_.begin(), items_.end(), [id](const auto& m) { return m.id == id; });
  return it == items_.end() ? nullptr : &*it;
}

Measurement* MeasurementModel::findMutable(int id) {
  return const_cast<Measurement*>(std::as_const(*this).find(id));
}

int MeasurementModel::add(MeasureKind kind, std::vector<glm::dvec3> points, int normalAxis) {
  Measurement m;
  m.id = nextId_++;
  m.kind = kind;
  m.points = std::move(points);
  m.normalAxis = normalAxis;
  items_.push_back(std::move(m));
  selected_ = items_.back().id;
  changed.notify();
  return selected_;
}

void MeasurementModel::movePoint(int id, int index, const glm::dvec3& voxel) {
  Measurement* m = findMutable(id);
  if (!m || index < 0 || index >= int(m->points.size())) return;
  glm::dvec3 p = voxel;
  const bool roi = m->kind == MeasureKind::Ellipse || m->kind == MeasureKind::Rect;
  if (roi && m->normalAxis >= 0) p[m->normalAxis] = m->points[0][m->normalAxis];
  m->points[size_t(index)] = p;
  changed.notify();
}

void MeasurementModel::remove(int id) {
  std::erase_if(items_, [id](const auto& m) { return m.id == id; });
  if (selected_ == id) selected_ = 0;
  changed.notify();
}

void MeasurementModel::clear() {
  items_.clear();
  selected_ = 0;
  changed.notify();
}

void MeasurementModel::select(int id) {
  selected_ = find(id) ? id : 0;
  changed.notify();
}

void MeasurementModel::setTool(MeasureTool t) {
  tool_ = t;
  changed.notify();
}

void MeasurementModel::setShowInExports(bool on) {
  showInExports_ = on;
  changed.notify();
}

std::optional<int> MeasurementModel::addPick(const glm::dvec3& voxel) {
  if (!pendingPick_) {
    pendingPick_ = voxel;
    changed.notify();
    return std::nullopt;
  }
  const glm::dvec3 first = *pendingPick_;
  pendingPick_.reset();
  return add(MeasureKind::Distance, {first, voxel}, -1);
}

void MeasurementModel::cancelPick() {
  pendingPick_.reset();
  changed.notify();
}

bool pointOnSlice(const glm::dvec3& voxel, const SliceAxes& axes, int slice) {
  return std::abs(voxel[axes.nAxis] - slice) < 0.5;
}

bool shownOnSlice(const Measurement& m, const SliceAxes& axes, int slice) {
  if (m.points.empty()) return false;
  if (m.kind == MeasureKind::Ellipse || m.kind == MeasureKind::Rect)
    return m.normalAxis == axes.nAxis && std::lround(m.points[0][axes.nAxis]) == slice;
  return std::all_of(m.points.begin(), m.points.end(),
                     [&](const glm::dvec3& p) { return pointOnSlice(p, axes, slice); });
}

glm::dvec3 clampToVolume(const glm::dvec3& voxel, const glm::ivec3& dims) {
  return glm::clamp(voxel, glm::dvec3(-0.5), glm::dvec3(dims) - 0.5);
}

RoiStats measurementStats(const Volume& v, const Measurement& m) {
  PlaneRoi roi;
  roi.shape = m.kind == MeasureKind::Rect ? RoiShape::Rect : RoiShape::Ellipse;
  roi.normalAxis = std::clamp(m.normalAxis, 0, 2);
  roi.a = m.points.at(0);
  roi.b = m.points.at(1);
  return roiStats(v, roi);
}

RoiPeak measurementPeak(const Volume& v, const Measurement& m) {
  PlaneRoi roi;
  roi.shape = m.kind == MeasureKind::Rect ? RoiShape::Rect : RoiShape::Ellipse;
  roi.normalAxis = std::clamp(m.normalAxis, 0, 2);
  roi.a = m.points.at(0);
  roi.b = m.points.at(1);
  return roiPeak(v, roi);
}

namespace {

std::string number(const std::optional<double>& x, int decimals) {
  if (!x) return "—";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, *x);
  return buf;
}

}  // namespace

std::string measurementText(const Volume& v, const Measurement& m) {
  if (int(m.points.size()) < pointCount(m.kind)) return "—";
  const auto& p = m.points;
  switch (m.kind) {
    case MeasureKind::Distance:
      return number(distanceMm(v, p[0], p[1]), 1) + " mm";
    case MeasureKind::Angle:
      return number(angleDeg(v, p[0], p[1], p[2]), 1) + "°";
    case MeasureKind::Ellipse:
    case MeasureKind::Rect:
      break;
  }
  RoiStats s = measurementStats(v, m);
  if (v.suv) {  // PET with its SUV scale: SUVmean, SD, min, max, peak (the scale is linear)
    const RoiPeak peak = measurementPeak(v, m);
    std::optional<double> suvPeak = peak.mean;
    for (auto* x : {&s.mean, &s.sd, &s.min, &s.max, &suvPeak})
      if (*x) *x = v.suv->toSuv(**x);
    return "SUVmean " + number(s.mean, 3) + "  SD " + number(s.sd, 3) + "  min " +
           number(s.min, 3) + "  SUVmax " + number(s.max, 3) + "  SUVpeak " +
           (suvPeak ? number(suvPeak, 3) : std::string("— (no room for 1 cm³)")) + " " +
           v.suv->unit + ", " + number(s.areaMm2, 1) + " mm², " + std::to_string(s.pixels) + " px";
  }
  return "mean " + number(s.mean, 1) + "  SD " + number(s.sd, 1) + "  min " + number(s.min, 0) +
         "  max " + number(s.max, 0) + " " + valueUnit(v) + ", " + number(s.areaMm2, 1) + " mm², " +
         std::to_string(s.pixels) + " px";
}

}  // namespace voxray
