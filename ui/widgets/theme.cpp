#include "theme.h"

#include <iterator>

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

// The classes a platform theme may give palettes of their own (QPlatformTheme's
// MenuBarPalette, MenuPalette): a light desktop's menu bar must not stay light in Dark.
constexpr const char* kMenuClasses[] = {"QMenuBar", "QMenu"};

struct Platform {
  QString style;
  QPalette palette;
  QPalette menuPalettes[2];  // kMenuClasses' palettes as the platform gave them
};

const Platform& platform() {
  static const Platform p{
      QApplication::style()->name(),
      QApplication::palette(),
      {QApplication::palette(kMenuClasses[0]), QApplication::palette(kMenuClasses[1])}};
  return p;
}

// PALETTE for the whole application, the menu bar and menus by name: setting the
// application's palette drops the class palettes, but a platform theme puts its own back
// when the desktop's theme changes.
void setPalettes(const QPalette& palette, const QPalette (&menus)[2]) {
  QApplication::setPalette(palette);
  for (size_t i = 0; i < std::size(kMenuClasses); ++i)
    QApplication::setPalette(menus[i], kMenuClasses[i]);
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
    const QPalette p = name == "Dark" ? darkPalette() : QApplication::style()->standardPalette();
    setPalettes(p, {p, p});
    return;
  }
  QApplication::setStyle(QStyleFactory::create(system.style));
  setPalettes(system.palette, system.menuPalettes);
}

}  // namespace voxray::ui
