#include "tf_drag.h"

#include <algorithm>
#include <cmath>

#include "voxray/engine/volume_property.h"

namespace voxray {

namespace {

// Where the table shows something: the middle of the HU range whose opacity is above 0
// (of all its points when none is), the point a stretch keeps in place.
double visibleCentre(const std::vector<ControlPoint>& points) {
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (const ControlPoint& c : points) {
    if (c.rgba.a <= 0.0) continue;
    lo = any ? std::min(lo, c.hu) : c.hu;
    hi = any ? std::max(hi, c.hu) : c.hu;
    any = true;
  }
  if (!any && !points.empty()) lo = points.front().hu, hi = points.back().hu;
  return 0.5 * (lo + hi);
}

}  // namespace

RenderParams dragTransferFunction(const RenderParams& start, glm::dvec2 moved, double huSpan,
                                  bool opacity) {
  RenderParams p = start;
  const double shift = moved.y * huSpan;
  const double stretch = std::exp2(2.0 * moved.x);
  switch (start.mode) {
    case Mode::Iso:
      p.isoLo = start.isoLo + shift;
      p.isoHi = std::max(p.isoHi, p.isoLo);
      break;
    case Mode::Mip: {
      // Width 0 means the volume's range: the drag starts from the span it is given.
      double width = start.windowWidth > 0.0 ? start.windowWidth : huSpan;
      double level = start.windowWidth > 0.0 ? start.windowLevel : 0.0;
      p.windowWidth = std::max(1.0, width * stretch);
      p.windowLevel = level + shift;
      break;
    }
    case Mode::Dvr: {
      // The table on screen (a preset with its shift, or a custom table).
      std::vector<ControlPoint> points = renderTable(volumePropertyOf(start));
      const double centre = visibleCentre(points);
      const double gain = std::exp2(3.0 * moved.y);
      for (ControlPoint& c : points) {
        if (opacity)
          c.rgba.a = std::min(1.0, c.rgba.a * gain);
        else
          c.hu = centre + (c.hu - centre) * stretch + shift;
      }
      p.preset.clear();
      p.presetShiftHu = 0.0;
      p.transferFunction = std::move(points);
      break;
    }
  }
  return p;
}

}  // namespace voxray
