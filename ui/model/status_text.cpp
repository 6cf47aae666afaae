#include "status_text.h"

#include <cstdio>

namespace voxray::ui {

std::string formatFrameStats(const FrameStats& s) {
  if (!s.any) return "no frame yet";
  char buf[64];
  if (s.fps <= 0.0) {  // one frame so far: no rate to tell
    std::snprintf(buf, sizeof buf, "%.0f ms%s", s.lastMs, s.interactive ? " (interactive)" : "");
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.1f fps · %.0f ms%s", s.fps, s.lastMs,
                s.interactive ? " (interactive)" : "");
  return buf;
}

std::string formatWindowTitle(const std::string& name, const FrameStats& s,
                              const std::string& device) {
  std::string title;
  auto add = [&title](const std::string& part) {
    if (part.empty()) return;
    if (!title.empty()) title += " — ";
    title += part;
  };
  add(name);
  // The title is read at a glance: the interactive marker stays in the status bar only.
  FrameStats steady = s;
  steady.interactive = false;
  if (s.any) add(formatFrameStats(steady));
  add(device);
  add("Voxray");
  return title;
}

}  // namespace voxray::ui
