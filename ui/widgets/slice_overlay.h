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
  SliceAxes axes;  // its labels: the view's letters (mixed on an oblique plane)
  glm::dvec2 crosshair{0.0};
  // Screen directions (x right, y down) of the crosshair's two lines, the traces of the
  // other planes: the first drawn in planeColor(axes.uAxis), upright while nothing is turned.
  std::array<glm::dvec2, 2> traces{glm::dvec2(0, 1), glm::dvec2(1, 0)};
  bool rotateHandles = false;  // draw the handles that turn the lines (rotationHandles)
  std::string planeNote;       // under the slice number: "oblique", the slab
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
QRectF crosshairBounds(const QFont& font, const QRect& r);

// The handles that turn the crosshair's lines: two on each line, either side of CENTRE
// (widget pixels), within R's crosshair bounds (in FONT) where there is room. Line i's handles are
// entries 2i and 2i+1.
std::array<QPointF, 4> rotationHandles(const QFont& font, const QRect& r, QPointF centre,
                                       const std::array<glm::dvec2, 2>& traces);
constexpr double kRotateHandleRadius = 5.0;

// A round scale-bar length (1, 2 or 5 times a power of ten) near TARGET_MM.
double niceLengthMm(double targetMm);

// The scale bar in the bottom right corner of R (about a fifth of its width) and its label,
// whose rectangle holds the whole text in FM's font, inside R.
struct ScaleBar {
  QLineF bar;
  QRectF label;
  QString text;  // "50 mm"
};
ScaleBar scaleBarLayout(const QFontMetricsF& fm, double mmPerPixel, const QRect& r);

}  // namespace voxray::ui
