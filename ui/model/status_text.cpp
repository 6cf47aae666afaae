#include "status_text.h"

#include <cstdio>

namespace voxray::ui {

namespace {
constexpr double kFpsSmoothing = 0.3;  // weight of the newest frame in the fps average
}

std::string formatFrameStats(const FrameStats& s) {
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

std::string formatWindowTitle(const std::string& name) {
  return name.empty() ? "Voxray" : name + " — Voxray";
}

double FrameRateMeter::frameAt(double nowS) {
  double gap = nowS - lastAt_;
  if (lastAt_ < 0.0 || gap <= 0.0 || gap > kIdleGapS) {
    fps_ = 0.0;
  } else {
    double instant = 1.0 / gap;
    fps_ = fps_ <= 0.0 ? instant : kFpsSmoothing * instant + (1.0 - kFpsSmoothing) * fps_;
  }
  lastAt_ = nowS;
  return fps_;
}

}  // namespace voxray::ui
