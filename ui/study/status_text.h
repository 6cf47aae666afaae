#pragma once
// The frame statistics as the status bar shows them, and the window title (the document
// name only: a title that changed every frame could not be read, and the device is in the
// status bar).
#include <string>

#include <glm/glm.hpp>

#include "no_qt.h"

namespace voxray {

struct FrameRateStats {
  bool any = false;  // false until the first frame
  double fps = 0.0;  // 0 = no rate: frames did not follow each other closely enough
  double lastMs = 0.0;
  bool interactive = false;
};

// "12.5 fps · 80 ms", "12.5 fps · 80 ms (interactive)", "80 ms" when there is no rate (one
// frame after a pause) or "no frame yet".
std::string formatFrameStats(const FrameRateStats& s);

// The HU probe's two lines: "-998 HU  [128, 200, 75]" and "R 12.3  A 45.6  S 78.9 mm"
// (the user's convention: R/L, A/P, S/I letters rather than signed LPS). Outside the volume
// the value reads "—" and the position is still given.
struct CursorProbe;
std::string formatCursorProbe(const CursorProbe& p);
// A patient position as "R 12.3  A 45.6  S 78.9 mm".
std::string formatPatientMm(const glm::dvec3& lpsMm);

// "NAME — Voxray", or "Voxray" with no document. NAME is the document name (a file or
// folder name, never patient data).
std::string formatWindowTitle(const std::string& name);

// Frames per second over frames that follow each other: a frame after a pause (the view was
// idle, nothing to render) starts the rate afresh instead of counting the idle time, which
// showed "0.0 fps · 32 ms" for a 32 ms frame.
class FrameRateMeter {
 public:
  // Seconds between frames beyond which the view counts as having been idle.
  static constexpr double kIdleGapS = 1.0;
  // The rate after a frame finished at NOW (seconds, any monotonic clock); 0 = no rate yet.
  double frameAt(double nowS);

 private:
  double lastAt_ = -1.0, fps_ = 0.0;
};

}  // namespace voxray
