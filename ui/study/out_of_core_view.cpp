#include "out_of_core_view.h"

#include <algorithm>

namespace voxray {

size_t deviceHeadroomBytes(size_t globalMemBytes) {
  return globalMemBytes / 8 + (size_t(256) << 20);
}

OutOfCoreChoice chooseOutOfCore(size_t volumeBytes, size_t globalMemBytes, size_t userBudgetBytes) {
  OutOfCoreChoice c;
  if (userBudgetBytes > 0) {
    c.outOfCore = volumeBytes > userBudgetBytes;
    c.budgetBytes = userBudgetBytes;
    return c;
  }
  const size_t headroom = deviceHeadroomBytes(globalMemBytes);
  const size_t usable = globalMemBytes > headroom ? globalMemBytes - headroom : 0;
  c.outOfCore = globalMemBytes > 0 && volumeBytes > usable;
  c.budgetBytes = usable;
  return c;
}

OutOfCoreParams outOfCoreParams(const RenderParams& p, bool hasLabels, bool hasOverlay,
                                double spacingZMm) {
  OutOfCoreParams o{p, {}};
  RenderParams& q = o.params;
  if (hasLabels) o.off.emplace_back("labels");
  if (hasOverlay) o.off.emplace_back("fusion");
  if (q.lighting != Lighting::Phong) {
    o.off.push_back(std::string(toString(q.lighting)) + " (lit by phong)");
    q.lighting = Lighting::Phong;
  }
  if (q.preintegrate && q.mode == Mode::Dvr) {
    // The parts' frames set up no pre-integrated table (out_of_core.cpp).
    o.off.emplace_back("pre-integration");
  }
  q.preintegrate = false;
  // Segments grouped by adaptive steps and the image-space adaptive pass are speed-ups the
  // parts do not take (multi_device.h): the frame is the exact one they approximate.
  q.adaptiveError = 0.0;
  q.adaptiveImage = -1.0;
  // The parts' apron of 4 holds a step of 2 slices (out_of_core.h); 0 is half a voxel.
  const double longest = 2.0 * spacingZMm;
  if (q.stepMm > longest) {
    q.stepMm = longest;
    o.off.emplace_back("steps over 2 slices");
  }
  return o;
}

std::string resolutionNote(const OutOfCoreStats& s) {
  if (s.fullResolution) return "";
  std::string note = "Not at full resolution (" + std::to_string(s.partsFull) + " of " +
                     std::to_string(s.parts) + " parts)";
  if (s.shown == "preview") note += "; quick preview, the coarse level on its way";
  if (s.deviceOutOfMemory) note += "; device out of memory";
  return note;
}

std::string limitsNote(const std::vector<std::string>& off) {
  if (off.empty()) return "";
  std::string note = "Out of core, off: ";
  for (size_t i = 0; i < off.size(); ++i) note += (i ? ", " : "") + off[i];
  return note;
}

}  // namespace voxray
