#include "status_text.h"

#include <cmath>
#include <cstdio>

#include "slice_image.h"

namespace voxray {

namespace {}

std::string formatFrameStats(const FrameRateStats& s) {
  if (!s.any) return "no frame yet";
  char buf[64];
  if (s.fps <= 0.0) {  // no rate to tell
    std::snprintf(buf, sizeof buf, "%.0f ms%s", s.lastMs, s.interactive ? " (interactive)" : "");
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.1f fps · %.0f ms%s", s.fps, s.lastMs,
                s.interactive ? " (interactive)" : "");
  return buf;
}

std::string formatPatientMm(const glm::dvec3& mm) {
  // LPS: +x is the patient's left, +y posterior, +z superior.
  static const char* pos[] = {"L", "P", "S"};
  static const char* neg[] = {"R", "A", "I"};
  std::string out;
  char buf[48];
  for (int a = 0; a < 3; ++a) {
    // -0.0 and tiny negatives print as 0.0 under the positive letter.
    const double rounded = std::round(mm[a] * 10.0) / 10.0;
    std::snprintf(buf, sizeof buf, "%s%s %.1f", a ? "  " : "", rounded < 0 ? neg[a] : pos[a],
                  std::abs(rounded));
    out += buf;
  }
  return out + " mm";
}

std::string formatCursorProbe(const CursorProbe& p) {
  char buf[96];
  if (p.inside)
    std::snprintf(buf, sizeof buf, "%.*f %s  [%d, %d, %d]", p.decimals, p.value, p.unit.c_str(),
                  p.voxel.x, p.voxel.y, p.voxel.z);
  else
    std::snprintf(buf, sizeof buf, "— (outside the volume)");
  return std::string(buf) + "\n" + formatPatientMm(p.patientMm);
}

std::string formatWindowTitle(const std::string& name) {
  return name.empty() ? "Voxray" : name + " — Voxray";
}

double FrameRateMeter::frameAt(double nowS, bool interactive) {
  if (!interactive) {  // the drag (if any) is over
    dragFrames_.clear();
    return 0.0;
  }
  if (!dragFrames_.empty() && !(nowS - dragFrames_.back() <= kIdleGapS)) dragFrames_.clear();
  dragFrames_.push_back(nowS);
  if (dragFrames_.size() > kWindow) dragFrames_.pop_front();
  const double span = dragFrames_.back() - dragFrames_.front();
  if (dragFrames_.size() < kMinFrames || !(span > 0.0)) return 0.0;
  return double(dragFrames_.size() - 1) / span;
}

}  // namespace voxray
