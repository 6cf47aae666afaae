#pragma once
// Window/level for slice display, in the volume's physical unit (HU for CT), with the
// presets radiologists expect (the values RadiAnt and Horos ship).
#include <cstdint>
#include <string>
#include <vector>

#include "notifier.h"
#include "voxray/engine/param_spec.h"

namespace voxray {

struct WindowLevel {
  double width = 400.0;
  double level = 40.0;
};

struct WindowLevelPreset {
  std::string name;
  WindowLevel wl;
};
const std::vector<WindowLevelPreset>& windowLevelPresets();

// The values a window may take, declared with the other parameters' domains: the slice
// group's controls take their ranges from here.
struct WindowLevelDomain {
  ParamDomain width, level;
};
const WindowLevelDomain& windowLevelDomain();

// DICOM-style linear ramp: level - width/2 maps to 0, level + width/2 to 255.
uint8_t mapToGrey(double value, const WindowLevel& wl);
// The same ramp from LO (black) over WIDTH (to white), for a window given by its low end
// (a movie cine over the volume's whole range): the one grey mapping of slices and cines.
uint8_t greyRamp(double value, double lo, double width);

// A mouse drag from START by (dx, dy) pixels: right widens the window, down raises the
// level (as in 3D Slicer). Sensitivity scales with the window so narrow windows stay fine.
WindowLevel dragWindowLevel(const WindowLevel& start, double dx, double dy);

class WindowLevelModel {
 public:
  const WindowLevel& value() const { return wl_; }
  // Where the value came from when the study opened ("DICOM window", "CT default ...");
  // empty once the user has changed it. Shown wherever W/L is shown.
  const std::string& source() const { return source_; }
  void set(const WindowLevel& wl);  // the user's value: clears the source
  // A study's initial window (initialWindow in study_state.h) and where it came from.
  void reset(const WindowLevel& wl, std::string source);
  // Returns false (and changes nothing) for an unknown name.
  bool applyPreset(const std::string& name);
  Notifier<> changed;

 private:
  WindowLevel wl_;
  std::string source_;
};

// "W 400  L 40", with the source on a second line while there is one.
std::string formatWindowLevel(const WindowLevel& wl, const std::string& source);

}  // namespace voxray
