#pragma once
// What a slice view draws over the slice: orientation letters, the crosshair, the clip box
// edges, slice number, window/level, the value and position under the cursor, a scale bar.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <QPainter>

#include "slice_clip.h"
#include "window_level.h"

namespace voxray::ui {

struct SliceOverlay {
  SliceAxes axes;
  glm::dvec2 crosshair{0.0};
  std::array<SliceClipEdge, 4> clipEdges{};
  bool showClip = false;
  bool clipActive = true;  // the slice lies inside the box across the view
  int slice = 0, sliceCount = 0;
  WindowLevel wl;
  std::string wlSource;  // where the window came from (WindowLevelModel::source)
  double mmPerWidgetPixel = 1.0;
  bool hasCursor = false;
  std::string cursorText;               // the HU probe's lines (formatCursorProbe)
  std::vector<std::string> studyLines;  // patient and study text (study_text.h), when shown
};

using SliceToWidget = std::function<QPointF(double u, double v)>;
void drawSliceOverlay(QPainter& p, const SliceOverlay& o, const QRect& widget,
                      const SliceToWidget& toWidget);

// Where the crosshair lines may run in widget R: R less the bands of the orientation letters
// (in P's font, bold), so that no line crosses a letter.
QRectF crosshairBounds(const QPainter& p, const QRect& r);

// A round scale-bar length (1, 2 or 5 times a power of ten) near TARGET_MM.
double niceLengthMm(double targetMm);

}  // namespace voxray::ui
