#include "theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyle>
#include <QStyleFactory>

namespace voxray::ui {

namespace {

QPalette darkPalette() {
  // Fusion's palette with dark roles; the 3D and slice views are black whatever the theme.
  QPalette p;
  const QColor window(45, 45, 48), base(30, 30, 32), text(220, 220, 220), dim(128, 128, 128);
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, window);
  p.setColor(QPalette::ToolTipBase, base);
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, window);
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, Qt::red);
  p.setColor(QPalette::Link, QColor(90, 160, 240));
  p.setColor(QPalette::Highlight, QColor(60, 120, 200));
  p.setColor(QPalette::HighlightedText, Qt::white);
  p.setColor(QPalette::PlaceholderText, dim);
  for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
    p.setColor(QPalette::Disabled, role, dim);
  return p;
}

struct Platform {
  QString style;
  QPalette palette;
};

const Platform& platform() {
  static const Platform p{QApplication::style()->name(), QApplication::palette()};
  return p;
}

}  // namespace

const QStringList& themeNames() {
  static const QStringList names = {"System", "Light", "Dark"};
  return names;
}

void applyTheme(const QString& name) {
  const Platform& system = platform();
  if (name == "Light" || name == "Dark") {
    QApplication::setStyle(QStyleFactory::create("Fusion"));
    QApplication::setPalette(name == "Dark" ? darkPalette()
                                            : QApplication::style()->standardPalette());
    return;
  }
  QApplication::setStyle(QStyleFactory::create(system.style));
  QApplication::setPalette(system.palette);
}

}  // namespace voxray::ui
