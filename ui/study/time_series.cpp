#include "time_series.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "measurement_model.h"
#include "slice_image.h"
#include "value_look.h"

namespace voxray {

void TimePlayer::setFps(double fps, int current, double nowS) {
  const double clamped = std::clamp(std::isfinite(fps) ? fps : kDefaultFps, kMinFps, kMaxFps);
  if (clamped == fps_) return;
  fps_ = clamped;
  if (playing_) {
    from_ = current;
    startS_ = nowS;
  }
  changed.notify();
}

void TimePlayer::setLoop(bool on) {
  if (on == loop_) return;
  loop_ = on;
  changed.notify();
}

void TimePlayer::play(int from, double nowS) {
  from_ = from;
  startS_ = nowS;
  if (playing_) return;
  playing_ = true;
  changed.notify();
}

void TimePlayer::pause() {
  if (!playing_) return;
  playing_ = false;
  changed.notify();
}

int TimePlayer::tick(double nowS, int count) {
  if (count <= 0) return 0;
  const int from = std::clamp(from_, 0, count - 1);
  if (!playing_) return from;
  // A small epsilon: a tick exactly on a frame boundary (n / fps) shows frame n.
  const long long steps = std::max(0LL, (long long)(std::floor((nowS - startS_) * fps_ + 1e-9)));
  const long long at = from + steps;
  if (loop_) return int(at % count);
  if (at >= count - 1) {
    from_ = count - 1;
    playing_ = false;
    changed.notify();
    return count - 1;
  }
  return int(at);
}

VolumeResidency::Use VolumeResidency::use(const void* key, size_t bytes) {
  Use out;
  auto it =
      std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
  out.upload = it == entries_.end();
  if (!out.upload) entries_.erase(it);
  entries_.insert(entries_.begin(), Entry{key, bytes});
  size_t total = residentBytes();
  while (entries_.size() > 1 && total > budget_) {
    out.evict.push_back(entries_.back().key);
    total -= entries_.back().bytes;
    entries_.pop_back();
  }
  return out;
}

bool VolumeResidency::preload(const void* key, size_t bytes) {
  if (resident(key) || residentBytes() + bytes > budget_) return false;
  entries_.push_back(Entry{key, bytes});
  return true;
}

void VolumeResidency::forget(const void* key) {
  std::erase_if(entries_, [&](const Entry& e) { return e.key == key; });
}

bool VolumeResidency::resident(const void* key) const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [&](const Entry& e) { return e.key == key; });
}

size_t VolumeResidency::residentBytes() const {
  size_t total = 0;
  for (const Entry& e : entries_) total += e.bytes;
  return total;
}

size_t residencyBudget(bool isGpu, size_t globalMemBytes) {
  if (!isGpu) return std::numeric_limits<size_t>::max();
  return globalMemBytes / 2;
}

double readoutValue(const Volume& v, double physical) {
  return v.suv ? v.suv->toSuv(physical) : physical;
}

std::string readoutUnit(const Volume& v) { return v.suv ? v.suv->unit : valueUnit(v); }

std::vector<double> timeIntensityAtVoxel(const VolumeSeries& series, const glm::dvec3& voxel) {
  std::vector<double> out;
  out.reserve(series.size());
  for (const auto& v : series) out.push_back(readoutValue(*v, sampleValue(*v, voxel)));
  return out;
}

std::vector<double> timeIntensityInRoi(const VolumeSeries& series, const Measurement& roi) {
  std::vector<double> out;
  out.reserve(series.size());
  for (const auto& v : series) {
    const RoiStats s = measurementStats(*v, roi);
    out.push_back(s.mean ? readoutValue(*v, *s.mean) : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

std::string timeIntensityCsv(const std::vector<double>& values, const std::string& what,
                             const std::string& unit) {
  std::string out = "time_point," + what + " (" + unit + ")\n";
  char buf[64];
  for (size_t t = 0; t < values.size(); ++t) {
    if (std::isnan(values[t]))
      std::snprintf(buf, sizeof buf, "%zu,\n", t);
    else
      std::snprintf(buf, sizeof buf, "%zu,%.10g\n", t, values[t]);
    out += buf;
  }
  return out;
}

}  // namespace voxray
