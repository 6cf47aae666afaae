#pragma once
// Fusion (issue 36): a second volume (PET, MR, a prior) drawn over the slice views' volume
// through a colour map. The overlay keeps its own grid: each slice pixel's patient point
// (LPS mm) is looked up in the overlay's voxels (trilinear, engine's samplePlane), so the
// two need not share dims, spacing or direction. The 3D view gets the same window and map
// as the engine's overlay table (Raycaster::setOverlay, overlayWindowTable).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "no_qt.h"
#include "notifier.h"
#include "time_follow.h"
#include "time_series.h"
#include "voxray/engine/plane_sampler.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/image.h"
#include "voxray/io/volume.h"

namespace voxray {

struct FusionSettings {
  bool on = true;
  std::string colormap = "hot-iron";  // hot-iron, rainbow, grey (overlayWindowTable's maps)
  // The window in the overlay's display unit (fusionUnit: SUV when the overlay has an SUV
  // scale, else its physical unit): transparent at and below LO, the map's end at HI.
  double lo = 0.0, hi = 1.0;
  double opacity = 0.5;  // of the slice overlay where it shows, 0 ... 1
  bool operator==(const FusionSettings&) const = default;
};

// The colour maps offered, in menu order.
const std::vector<std::string>& fusionColormaps();
// The unit the window and readouts use: the SUV's ("SUVbw") when the overlay has one.
std::string fusionUnit(const Volume& overlay);
// A display value (fusionUnit) as the overlay's physical value, and back.
double fusionToPhysical(const Volume& overlay, double display);
double fusionToDisplay(const Volume& overlay, double physical);

// The overlay's display values at each pixel of PLANE (row by row, x fastest): trilinear
// in its own voxels at the pixel's patient point; NaN outside its box.
std::vector<float> fusionValues(const Volume& overlay, const PlaneGrid& plane);
// The colour map's colour (0 ... 1) of a display VALUE under S's window.
glm::dvec3 fusionColour(const FusionSettings& s, const Volume& overlay, double value);
// RGBA8 of PLANE's size, premultiplied for none (straight alpha): the colour map's colour
// with alpha = opacity where the value is above LO, transparent elsewhere (below the window,
// outside the overlay, or S off). Throws Error (Input) for an unknown map or LO >= HI.
Image fusionImage(const Volume& overlay, const PlaneGrid& plane, const FusionSettings& s);
// The cursor readout's part for the overlay at PATIENTMM: "overlay 3.214 SUVbw", or
// "overlay: outside" beyond its box.
std::string fusionProbeText(const Volume& overlay, const glm::dvec3& patientMm);
// The 3D view's table for the overlay (physical units), as voxray-cli render --overlay-window.
TransferFunction fusionTable(const Volume& overlay, const FusionSettings& s);
// A first window: SUV 1 ... 6 for a PET with an SUV scale (uptake below SUV 1, most of the
// body's background, left transparent; the sphere phantom's 6.6 at the map's end), else
// the upper nine tenths of the stored range.
FusionSettings defaultFusion(const Volume& overlay);

// The overlay of one window: its volume, where it came from and how it is shown. A 4D
// overlay keeps every time point; overlay() is the one shown, by TimeFollow's rule: the
// study's time point when both have as many, else the overlay's own (setOwnTimePoint).
class FusionModel {
 public:
  const std::shared_ptr<const Volume>& overlay() const { return overlay_; }
  const VolumeSeries& series() const { return series_; }
  const TimeFollow& time() const { return time_; }
  const std::string& name() const { return name_; }
  bool active() const { return overlay_ && settings_.on; }
  const FusionSettings& settings() const { return settings_; }
  // What the user must know (no shared Frame of Reference with BASE), for the status bar.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // OVERLAY over BASE (its Frame of Reference checked), with defaultFusion's window.
  void setOverlay(std::shared_ptr<const Volume> overlay, std::string name, const Volume* base);
  // Every time point of a 4D overlay (one geometry, as loadVolumeSeries gives them); the window
  // is defaultFusion's of the time point shown first.
  void setOverlaySeries(VolumeSeries series, std::string name, const Volume* base);
  // The study's time slider moved (or another study opened): POINT of COUNT.
  void setMainTime(int point, int count);
  // The overlay's own time point, shown while it does not follow the study's.
  void setOwnTimePoint(int point);
  // Where the overlay was read from (a session saves it): its input (file or DICOM folder)
  // and load flags (input_flags.h). Empty: not from a file (a test's volume).
  const std::string& sourcePath() const { return sourcePath_; }
  const std::map<std::string, std::string>& sourceFlags() const { return sourceFlags_; }
  void setSource(std::string path, std::map<std::string, std::string> flags);
  void clear();
  // Another study under the overlay: its Frame of Reference checked again; settings stay.
  void setBase(const Volume* base);
  // Checked (fusionTable throws Error (Input) for a bad map or window) before it is taken.
  void setSettings(const FusionSettings& s);

  Notifier<> changed;

 private:
  void showTimePoint();  // overlay_ from series_ by time_; told when it changed
  std::shared_ptr<const Volume> overlay_;
  VolumeSeries series_;
  TimeFollow time_;
  std::string name_;
  std::string sourcePath_;
  std::map<std::string, std::string> sourceFlags_;
  FusionSettings settings_;
  std::vector<std::string> warnings_;
};

}  // namespace voxray
