#pragma once
// The frame statistics as the status bar shows them, and the window title (the document
// name only: a title that changed every frame could not be read, and the device is in the
// status bar).
#include <deque>
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

// A drag's frames per second, from the times its recent frames finished. A still frame has
// no rate, only its time: the instant rate of the sharp frame after a drag, or of a
// progressive pass, read "381.6 fps · 72 ms". A drag shows a rate once kMinFrames of its
// frames followed each other (none more than kIdleGapS apart), over at most kWindow.
class FrameRateMeter {
 public:
  static constexpr double kIdleGapS = 1.0;
  static constexpr size_t kMinFrames = 5, kWindow = 10;
  // The rate to show after a frame finished at NOW (seconds, any monotonic clock);
  // INTERACTIVE: a drag frame. 0 = no rate.
  double frameAt(double nowS, bool interactive);

 private:
  std::deque<double> dragFrames_;  // finish times of the drag's latest frames
};

}  // namespace voxray
