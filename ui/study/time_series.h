#pragma once
// A 4D series in the workstation (issue 36): playing its time points at a frame rate, which
// of them stay uploaded for the 3D view, and the time–intensity curve of a point or an ROI.
// Qt-free: the time panel's timer only asks TimePlayer which time point to show.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "notifier.h"
#include "voxray/io/volume.h"

namespace voxray {

struct Measurement;

// Every time point of an input in time order (one volume for a 3D input).
using VolumeSeries = std::vector<std::shared_ptr<const Volume>>;

// Plays time points at fps(): the point shown is the one play() started from plus the whole
// frames elapsed since, so a late timer tick skips to the right point instead of drifting.
// At the end it wraps when looping, else stops on the last point.
class TimePlayer {
 public:
  static constexpr double kMinFps = 0.5, kMaxFps = 60.0, kDefaultFps = 10.0;

  double fps() const { return fps_; }
  // Clamped to kMinFps..kMaxFps; while playing, the clock restarts from CURRENT at NOWS so
  // that the new rate does not jump to another point.
  void setFps(double fps, int current = 0, double nowS = 0.0);
  bool loop() const { return loop_; }
  void setLoop(bool on);
  bool playing() const { return playing_; }
  // Starts at FROM (the point shown) at NOWS (any monotonic clock, seconds).
  void play(int from, double nowS);
  void pause();
  // The point to show at NOWS of COUNT time points. Not playing: FROM, unchanged.
  int tick(double nowS, int count);

  Notifier<> changed;  // fps, loop or playing changed (not every tick)

 private:
  double fps_ = kDefaultFps;
  bool loop_ = true, playing_ = false;
  int from_ = 0;
  double startS_ = 0.0;
};

// Which time points' volumes stay uploaded on the render device: the most recently shown,
// within a byte budget, so that switching back to one needs no upload. The one shown is kept
// even when it alone exceeds the budget (it must be rendered).
class VolumeResidency {
 public:
  explicit VolumeResidency(size_t budgetBytes) : budget_(budgetBytes) {}
  struct Use {
    bool upload = false;             // KEY was not resident: upload it
    std::vector<const void*> evict;  // release these first (least recently shown first)
  };
  // KEY (a volume) is shown now and takes BYTES on the device.
  Use use(const void* key, size_t bytes);
  // KEY, not shown, to upload ahead (a time point not shown yet) when it fits beside what is
  // resident: true to upload it, kept as the least recently shown; false when it is resident
  // already or does not fit.
  bool preload(const void* key, size_t bytes);
  void forget(const void* key);  // KEY could not be uploaded after all
  void clear() { entries_.clear(); }
  bool resident(const void* key) const;
  size_t residentBytes() const;
  size_t budget() const { return budget_; }

 private:
  struct Entry {
    const void* key;
    size_t bytes;
  };
  size_t budget_;
  std::vector<Entry> entries_;  // most recently shown first
};

// The budget for a device: a CPU device reads the volume in place (the host holds every time
// point anyway), so all stay; a GPU keeps them within half its global memory, the other half
// left for frames, the light grid and other programs.
size_t residencyBudget(bool isGpu, size_t globalMemBytes);

// What a value reads as in the workstation: SUVbw when the volume has its SUV scale, else
// the physical value (HU, Bq/mL, ...).
double readoutValue(const Volume& v, double physical);
std::string readoutUnit(const Volume& v);

// The time–intensity curve: per time point the readout value (readoutValue) at VOXEL
// (nearest voxel), or of an ROI measurement its mean. NaN where a point lies outside that
// time point's volume, or an ROI covers no voxel.
std::vector<double> timeIntensityAtVoxel(const VolumeSeries& series, const glm::dvec3& voxel);
std::vector<double> timeIntensityInRoi(const VolumeSeries& series, const Measurement& roi);

// The curve as CSV: a header "time_point,<what> (<unit>)" then one line per time point
// (0-based) and its value (10 significant digits), or nothing after the comma for NaN.
std::string timeIntensityCsv(const std::vector<double>& values, const std::string& what,
                             const std::string& unit);

}  // namespace voxray
