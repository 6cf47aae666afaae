#include "fusion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "voxray/engine/overlay.h"
#include "voxray/io/error.h"

namespace voxray {

const std::vector<std::string>& fusionColormaps() {
  static const std::vector<std::string> maps{"hot-iron", "rainbow", "grey"};
  return maps;
}

std::string fusionUnit(const Volume& overlay) {
  return overlay.suv ? overlay.suv->unit : overlay.unit;
}

double fusionToPhysical(const Volume& overlay, double display) {
  return overlay.suv && overlay.suv->factor > 0.0 ? display / overlay.suv->factor : display;
}

double fusionToDisplay(const Volume& overlay, double physical) {
  return overlay.suv ? overlay.suv->toSuv(physical) : physical;
}

std::vector<float> fusionValues(const Volume& overlay, const PlaneGrid& plane) {
  std::vector<float> values =
      samplePlane(overlay, plane, Interp::Linear, std::numeric_limits<float>::quiet_NaN());
  if (overlay.suv)
    for (float& v : values) v = float(overlay.suv->toSuv(v));  // NaN stays NaN
  return values;
}

std::string fusionProbeText(const Volume& overlay, const glm::dvec3& patientMm) {
  PlaneGrid g;
  g.originMm = patientMm;
  g.size = {1, 1};
  const float v = fusionValues(overlay, g)[0];
  if (std::isnan(v)) return "overlay: outside";
  char text[64];
  std::snprintf(text, sizeof text, "overlay %.4g ", double(v));
  return text + fusionUnit(overlay);
}

namespace {
// The engine's table with opacity 1: its colour is the map's at each value (the same stops
// the 3D view uses), in display units.
TransferFunction displayTable(const FusionSettings& s) {
  return overlayWindowTable(s.lo, s.hi, s.colormap, 1.0);
}
}  // namespace

glm::dvec3 fusionColour(const FusionSettings& s, const Volume&, double value) {
  return glm::dvec3(displayTable(s).evaluate(value));
}

Image fusionImage(const Volume& overlay, const PlaneGrid& plane, const FusionSettings& s) {
  const TransferFunction tf = displayTable(s);  // throws for a bad map or window
  Image out(plane.size.x, plane.size.y);
  if (!s.on) return out;
  const std::vector<float> values = fusionValues(overlay, plane);
  const auto alpha = uint8_t(std::lround(std::clamp(s.opacity, 0.0, 1.0) * 255.0));
  for (size_t i = 0; i < values.size(); ++i) {
    const float v = values[i];
    if (!(v > s.lo)) continue;  // NaN (outside the overlay) or below the window
    const glm::dvec4 c = tf.evaluate(v);
    uint8_t* px = &out.rgba[i * 4];
    for (int k = 0; k < 3; ++k) px[k] = uint8_t(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
    px[3] = alpha;
  }
  return out;
}

TransferFunction fusionTable(const Volume& overlay, const FusionSettings& s) {
  return overlayWindowTable(fusionToPhysical(overlay, s.lo), fusionToPhysical(overlay, s.hi),
                            s.colormap, s.opacity);
}

FusionSettings defaultFusion(const Volume& overlay) {
  FusionSettings s;
  if (overlay.suv) {
    s.lo = 1.0;
    s.hi = 6.0;
    return s;
  }
  const ValueRange r = storedRange(overlay);
  const double lo = overlay.toPhysical(r.min), hi = overlay.toPhysical(r.max);
  s.lo = lo + 0.1 * (hi - lo);
  s.hi = hi > s.lo ? hi : s.lo + 1.0;
  return s;
}

void FusionModel::setOverlay(std::shared_ptr<const Volume> overlay, std::string name,
                             const Volume* base) {
  VolumeSeries one;
  if (overlay) one.push_back(std::move(overlay));
  setOverlaySeries(std::move(one), std::move(name), base);
}

void FusionModel::setOverlaySeries(VolumeSeries series, std::string name, const Volume* base) {
  if (series.empty() || !series.front()) return clear();
  series_ = std::move(series);
  time_.setCount(int(series_.size()));
  time_.setOwn(0);  // a new overlay starts at its first time point (unless it follows)
  overlay_ = series_[size_t(time_.shown())];
  settings_ = defaultFusion(*overlay_);
  warnings_ = base ? overlayWarnings(*base, *overlay_) : std::vector<std::string>{};
  name_ = std::move(name);
  sourcePath_.clear();  // the caller that read it from a file says where (setSource)
  sourceFlags_.clear();
  changed.notify();
}

void FusionModel::setMainTime(int point, int count) {
  time_.setMain(point, count);
  showTimePoint();
}

void FusionModel::setOwnTimePoint(int point) {
  time_.setOwn(point);
  showTimePoint();
}

void FusionModel::showTimePoint() {
  if (series_.empty()) return;
  const std::shared_ptr<const Volume>& shown = series_[size_t(time_.shown())];
  if (shown == overlay_) return;
  overlay_ = shown;  // the same geometry and Frame of Reference: warnings and window stay
  changed.notify();
}

void FusionModel::setSource(std::string path, std::map<std::string, std::string> flags) {
  sourcePath_ = std::move(path);
  sourceFlags_ = std::move(flags);
}

void FusionModel::clear() {
  if (!overlay_) return;
  overlay_.reset();
  series_.clear();
  time_.setCount(1);
  name_.clear();
  sourcePath_.clear();
  sourceFlags_.clear();
  warnings_.clear();
  changed.notify();
}

void FusionModel::setBase(const Volume* base) {
  if (!overlay_) return;
  warnings_ = base ? overlayWarnings(*base, *overlay_) : std::vector<std::string>{};
  changed.notify();
}

void FusionModel::setSettings(const FusionSettings& s) {
  overlayWindowTable(s.lo, s.hi, s.colormap, 1.0);  // throws Error (Input) when bad
  if (s == settings_) return;
  settings_ = s;
  changed.notify();
}

}  // namespace voxray
