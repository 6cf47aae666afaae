#include "adaptive_quality.h"

#include <algorithm>
#include <cmath>

namespace voxray {

namespace {

bool same(const DragSetting& a, const DragSetting& b) {
  // The scheduler reads USED back from the frame's pixel size: allow its rounding.
  return std::abs(a.scale - b.scale) <= 0.02 * b.scale &&
         std::abs(a.stepVoxels - b.stepVoxels) <= 0.02 * b.stepVoxels;
}

// The mean of the middle half of MS: a median's robustness with less noise.
double middleMean(std::vector<double> ms) {
  std::sort(ms.begin(), ms.end());
  const size_t lo = ms.size() / 4, hi = ms.size() - ms.size() / 4;
  double sum = 0.0;
  for (size_t i = lo; i < hi; ++i) sum += ms[i];
  return sum / double(hi - lo);
}

}  // namespace

AdaptiveQuality::AdaptiveQuality(double targetFps, DragSetting start, AdaptiveLimits limits)
    : targetFps_(std::max(targetFps, 1.0)),
      baseStep_(start.stepVoxels),
      limits_(limits),
      setting_(fromWork(work(start))) {}

void AdaptiveQuality::setTargetFps(double fps) { targetFps_ = std::max(fps, 1.0); }

double AdaptiveQuality::work(const DragSetting& s) const {
  return s.scale * s.scale * baseStep_ / s.stepVoxels;
}

DragSetting AdaptiveQuality::fromWork(double w) const {
  const double lo = limits_.minScale, hi = limits_.maxScale;
  if (w >= lo * lo) return {std::min(std::sqrt(w), hi), baseStep_};
  return {lo, baseStep_ * std::min(lo * lo / std::max(w, 1e-9), limits_.maxStepFactor)};
}

void AdaptiveQuality::record(double ms, const DragSetting& used) {
  if (!(ms > 0.0) || !same(used, setting_)) return;
  recent_.push_back(ms);
  const size_t window = size_t(std::max(limits_.window, 1));
  if (recent_.size() % window != 0) return;
  const size_t kept = window * size_t(std::max({limits_.history, limits_.strikes, 1}));
  if (recent_.size() > kept) recent_.erase(recent_.begin(), recent_.end() - long(kept));
  const double miss = middleMean(recent_) * targetFps_ / 1000.0;  // > 1: too slow
  const double off = std::abs(std::log(miss));
  const bool full = recent_.size() >= kept;
  if (off > std::log1p(limits_.bigMiss)) {
    change(miss, !full);
  } else if (off > std::log1p(limits_.band)) {
    if (++strikeCount_ >= limits_.strikes) change(miss, !full);
  } else {
    strikeCount_ = 0;
    if (reaimDue_ && full) {
      reaimDue_ = false;
      if (off > std::log1p(limits_.reaim)) change(miss, false);
    }
  }
}

void AdaptiveQuality::change(double miss, bool fewFrames) {
  const DragSetting next = fromWork(work(setting_) / miss);
  if (same(next, setting_)) return;  // at a limit: nothing left to change
  setting_ = next;
  recent_.clear();
  strikeCount_ = 0;
  reaimDue_ = fewFrames;
  ++changes_;
}

}  // namespace voxray
