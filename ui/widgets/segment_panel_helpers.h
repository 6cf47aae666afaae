#pragma once
// What the Segments panel's files share (segment_panel*.cpp): the list's columns, new
// segments' colours and the spin boxes' make.
#include <cmath>
#include <optional>

#include <QColor>
#include <QDoubleSpinBox>
#include <QString>
#include <glm/glm.hpp>

namespace voxray::ui {

// kDisplay3d last: a combo box per row (3D: surface / in volume / hidden).
enum Column { kVisible, kColour, kName, kOpacity, kCategory, kType, kDisplay3d, kColumns };

// New segments' colours in turn: bone first, then colours far apart from it and each other.
inline glm::vec3 nextColour(size_t n) {
  static const glm::vec3 colours[] = {
      {0.95f, 0.90f, 0.75f}, {0.85f, 0.25f, 0.20f}, {0.30f, 0.70f, 0.30f}, {0.25f, 0.45f, 0.90f},
      {0.95f, 0.80f, 0.15f}, {0.80f, 0.35f, 0.80f}, {0.20f, 0.80f, 0.80f}, {0.95f, 0.55f, 0.15f}};
  return colours[n % (sizeof(colours) / sizeof(colours[0]))];
}

inline QColor toQColor(glm::vec3 c) { return QColor::fromRgbF(c.r, c.g, c.b); }

inline QString number(std::optional<double> v, int decimals = 1) {
  return v ? QString::number(*v, 'f', decimals) : QString();
}

inline QDoubleSpinBox* spin(double lo, double hi, double value, double step, int decimals,
                            const QString& suffix, const QString& tip) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(decimals);
  s->setSingleStep(step);
  s->setValue(value);
  s->setSuffix(suffix);
  s->setToolTip(tip);
  s->setKeyboardTracking(false);
  return s;
}

}  // namespace voxray::ui
