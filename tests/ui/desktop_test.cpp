// Issue 18 item 11, what every desktop viewer has: undo/redo through the Edit menu with a
// drag as one step, Help's shortcuts and About, a tooltip on every panel control, and the
// 3D view's orientation marker.
#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QMenu>
#include <QMenuBar>
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QToolButton>

#include "help_dialogs.h"
#include "orientation_marker.h"
#include "slice_overlay.h"
#include "theme.h"
#include "volume_overlay.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

// The action a user finds in the menus (walked as shown: a dock's toggle action belongs to
// the dock, not to the menu bar).
QAction* findInMenu(const QList<QAction*>& actions, const QString& text) {
  for (QAction* a : actions) {
    if (a->text().remove('&') == text) return a;
    if (a->menu())
      if (QAction* found = findInMenu(a->menu()->actions(), text)) return found;
  }
  return nullptr;
}

QAction* menuAction(QMenuBar& bar, const QString& text) {
  if (QAction* a = findInMenu(bar.actions(), text)) return a;
  qFatal("no menu action '%s'", qPrintable(text));
}

// Mean position of the pixels within 12 of COLOUR in each channel; (-1, -1) when none.
QPointF meanOf(const QImage& img, QColor colour) {
  QPointF sum;
  int n = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      QColor c = img.pixelColor(x, y);
      if (std::abs(c.red() - colour.red()) <= 12 && std::abs(c.green() - colour.green()) <= 12 &&
          std::abs(c.blue() - colour.blue()) <= 12) {
        sum += QPointF(x, y);
        ++n;
      }
    }
  return n ? sum / n : QPointF(-1, -1);
}

QImage markerImage(double azimuth, double elevation) {
  Volume v = makeHeadPhantom(16);
  RenderParams p;
  p.camera.azimuthDeg = azimuth;
  p.camera.elevationDeg = elevation;
  QImage img(700, 700, QImage::Format_RGB32);  // the marker at its largest
  img.fill(Qt::black);
  QPainter painter(&img);
  drawOrientationMarker(painter, makeViewGeometry(v, p), img.size());
  return img;
}

}  // namespace

class DesktopTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;

 private slots:
  void init() { QVERIFY(fixture_.start()); }
  void cleanup() { fixture_.stop(); }

  void undoRedoTakeBackADragAsOneStep() {
    QAction* undo = menuAction(*fixture_.window->menuBar(), "Undo");
    QAction* redo = menuAction(*fixture_.window->menuBar(), "Redo");
    QCOMPARE(undo->shortcut(), QKeySequence(QKeySequence::Undo));
    QCOMPARE(redo->shortcut(), QKeySequence("Ctrl+Shift+Z"));
    QVERIFY(!undo->isEnabled());
    const double zoom = fixture_.models->render.params().camera.zoom;
    // A right drag zooms, one model change per move; the whole drag is one step.
    QWidget* view = &fixture_.window->volumeView();
    QPoint from(view->width() / 2, view->height() / 2);
    QTest::mousePress(view, Qt::RightButton, {}, from);
    for (int i = 1; i <= 6; ++i) {
      QMouseEvent move(QEvent::MouseMove, from - QPoint(0, 5 * i), view->mapToGlobal(from),
                       Qt::NoButton, Qt::RightButton, Qt::NoModifier);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::RightButton, {}, from - QPoint(0, 30));
    const double zoomed = fixture_.models->render.params().camera.zoom;
    QVERIFY2(zoomed > zoom * 1.2, qPrintable(QString::number(zoomed)));
    QVERIFY(undo->isEnabled());
    undo->trigger();
    QCOMPARE(fixture_.models->render.params().camera.zoom, zoom);
    QVERIFY(!undo->isEnabled());
    QVERIFY(redo->isEnabled());
    redo->trigger();
    QCOMPARE(fixture_.models->render.params().camera.zoom, zoomed);
  }

  void helpListsShortcutsAndAbout() {
    QString shortcuts = shortcutsHtml(*fixture_.window->menuBar());
    for (const char* expected : {"Ctrl+Z", "Ctrl+Shift+Z", "Ctrl+E", "Export screenshot", "Undo",
                                 "Ctrl+wheel", "reset the camera"})
      QVERIFY2(shortcuts.contains(expected), expected);
    QVERIFY(menuAction(*fixture_.window->menuBar(), "About Voxray"));
    QString about = aboutHtml("Test device 7");
    QVERIFY(about.contains("Test device 7"));
    QVERIFY(about.contains(QApplication::applicationVersion()));
    QVERIFY(about.contains("LGPL"));
    QVERIFY(about.contains("Stanford"));
    // The sample CT is BSD-2-Clause: its copyright notice must reach the user.
    QVERIFY(about.contains("Chris Rorden"));
    QVERIFY(about.contains("BSD-2-Clause"));
  }

  // Issue 41 item 6: About left out FFmpeg and x264 (GPL), libcurl, NIfTI, Teem and MetaIO,
  // and gave a path in the source tree for the sample data's licence.
  void aboutListsEveryLibraryAndTheDataLicence() {
    const QString about = aboutHtml("cpu");
    for (const char* expected :
         // NOLINTNEXTLINE(bugprone-suspicious-missing-comma): one row, split over two lines
         {"<td>FFmpeg (libavcodec, libavformat, libavutil, libswscale)</td><td>MP4 export</td>"
          "<td>LGPL-2.1-or-later; as Debian builds it, with GPL parts: GPL-2.0-or-later</td>",
          "<td>x264</td><td>H.264 encoding of MP4 movies</td><td>GPL-2.0-or-later</td>",
          "<td>libcurl</td><td>DICOMweb PACS client</td><td>curl licence (MIT-style)</td>",
          "<td>NIfTI C library (nifti2, znz)</td><td>NIfTI import</td><td>public domain</td>",
          "<td>Teem</td><td>NRRD import</td><td>LGPL-2.1-or-later",
          "<td>MetaIO (from ITK)</td><td>MetaImage import</td><td>Apache-2.0</td>",
          "<td>DCMTK</td>", "<td>OpenJPEG</td>", "<td>OpenImageIO</td>", "<td>Qt</td>",
          "<td>nlohmann/json</td>", "<td>zlib</td>", "<td>GLM</td>", "<td>PoCL</td>",
          "© 2019 Chris Rorden, BSD-2-Clause licence.",
          "provided that its copyright notice, the licence's two conditions and its disclaimer "
          "go with it"})
      QVERIFY2(about.contains(QString(expected).toHtmlEscaped()) || about.contains(expected),
               expected);
    QVERIFY2(!about.contains("resources/"), qPrintable(about));  // no path in the sources
    const QString licence = sampleDataLicence();
    QVERIFY(licence.startsWith("BSD 2-Clause License\n\nCopyright (c) 2019, Chris Rorden"));
    QVERIFY(licence.contains("THIS SOFTWARE IS PROVIDED BY THE COPYRIGHT HOLDERS"));
  }

  // Issue 41 item 1: a closed Measurements dock had no way back.
  void measurementsDockReopensFromTheViewMenu() {
    auto* dock = fixture_.window->findChild<QDockWidget*>("measurementDock");
    QVERIFY(dock);
    QVERIFY(dock->isVisible());
    QAction* show = menuAction(*fixture_.window->menuBar(), "Measurements");
    QVERIFY(show->isCheckable());
    QVERIFY(show->isChecked());
    QVERIFY(dock->close());  // its title bar's close button
    QVERIFY(!dock->isVisible());
    QVERIFY(!show->isChecked());
    show->trigger();
    QVERIFY(dock->isVisible());
    QVERIFY(show->isChecked());
  }

  // Issue 41 item 3: the clip box's edges (255, 200, 0) were nearly the sagittal crosshair's
  // yellow (230, 200, 40). Every pair of overlay colours differs by 150 or more (RGB distance),
  // and a slice view draws its clip edges in that colour.
  void clipBoxColourIsClearOfThePlaneColours() {
    auto distance = [](QColor a, QColor b) {
      return std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue());
    };
    for (int axis = 0; axis < 3; ++axis)
      QVERIFY2(
          distance(clipBoxColor(), planeColor(axis)) >= 150.0,
          qPrintable(
              QString("axis %1: %2").arg(axis).arg(distance(clipBoxColor(), planeColor(axis)))));
    QImage img(200, 200, QImage::Format_RGB32);
    img.fill(Qt::black);
    {
      QPainter p(&img);
      SliceOverlay o;
      o.crosshair = {150, 150};
      o.showClip = true;
      o.clipEdges = {SliceClipEdge{0, true, 40}, SliceClipEdge{1, true, 120},
                     SliceClipEdge{2, false, 40}, SliceClipEdge{3, false, 120}};
      o.sliceCount = 1;
      drawSliceOverlay(p, o, img.rect(), [](double u, double v) { return QPointF(u, v); });
    }
    QCOMPARE(img.pixelColor(40, 80), clipBoxColor());  // the left edge, halfway down
  }

  void everyPanelControlHasATooltip() {
    auto* panel = fixture_.window->findChild<QScrollArea*>("controlPanel");
    QVERIFY(panel);
    QList<QWidget*> controls;
    for (QWidget* w : panel->widget()->findChildren<QWidget*>())
      if (qobject_cast<QAbstractButton*>(w) || qobject_cast<QComboBox*>(w) ||
          qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QAbstractSlider*>(w))
        controls << w;
    QVERIFY2(controls.size() > 25, qPrintable(QString::number(controls.size())));
    for (QWidget* w : controls)
      QVERIFY2(!w->toolTip().trimmed().isEmpty(),
               qPrintable(QString("%1 '%2' has no tooltip")
                              .arg(w->metaObject()->className(), w->objectName())));
  }

  // A maximised window on a 1920x1080 screen (less a title bar and a task bar) shows the
  // whole panel unscrolled (the light and camera groups folded); the light opens from its
  // header.
  void panelFitsA1080ScreenUnscrolled() {
    fixture_.window->resize(1920, 1000);
    QApplication::processEvents();
    auto* panel = fixture_.window->findChild<QScrollArea*>("controlPanel");
    QVERIFY(panel);
    QCOMPARE(panel->verticalScrollBar()->maximum(), 0);
    auto* light = panel->findChild<QGroupBox*>("LightGroup");
    auto* header = panel->findChild<QToolButton*>("foldLightGroup");
    QVERIFY(light && header);
    QVERIFY(!light->isVisible());
    QVERIFY(!panel->findChild<QGroupBox*>("CameraGroup")->isVisible());
    header->click();
    QVERIFY(light->isVisible());
    header->click();
    QVERIFY(!light->isVisible());
    for (const char* name : {"RenderingGroup", "QualityGroup", "SlicesGroup", "ClipGroup"}) {
      auto* group = panel->findChild<QGroupBox*>(name);
      QVERIFY2(group && group->isVisible(), name);
    }
  }

  // View → Theme: Dark and Light override the platform's palette, System goes back to it.
  void themeMenuSwitchesPaletteAndBack() {
    const QPalette system = QApplication::palette();
    auto pick = [this](const char* name) {
      auto* a = fixture_.window->menuBar()->findChild<QAction*>(QString("theme") + name);
      QVERIFY2(a, name);
      a->trigger();
      QVERIFY(a->isChecked());
    };
    pick("Dark");
    QVERIFY(QApplication::palette().color(QPalette::Window).lightness() < 80);
    QVERIFY(QApplication::palette().color(QPalette::WindowText).lightness() > 180);
    pick("Light");
    QVERIFY(QApplication::palette().color(QPalette::Window).lightness() > 180);
    pick("System");
    QCOMPARE(QApplication::palette().color(QPalette::Window), system.color(QPalette::Window));
    QCOMPARE(QApplication::palette().color(QPalette::Text), system.color(QPalette::Text));
  }

  // Issue 41 item 8: the dark theme left the menu bar light. Its own palette and the pixels
  // it paints (beside its last menu) follow the theme, and go back with Light.
  void menuBarFollowsTheTheme() {
    QMenuBar* bar = fixture_.window->menuBar();
    auto pick = [this](const char* name) {
      auto* a = fixture_.window->menuBar()->findChild<QAction*>(QString("theme") + name);
      QVERIFY2(a, name);
      a->trigger();
      QApplication::processEvents();
    };
    // The bar's empty area, right of its menus.
    auto barLightness = [bar] {
      const QImage img = bar->grab().toImage();
      const QRect menus = bar->actionGeometry(bar->actions().last());
      return QColor(img.pixel(std::min(img.width() - 4, menus.right() + 40), img.height() / 2))
          .lightness();
    };
    // As a platform theme with a menu bar palette of its own (gtk3, KDE) sets it at start.
    // (Here, offscreen or on Xvfb without a platform theme, the bar followed already.)
    QPalette themeBar = QApplication::palette();
    themeBar.setColor(QPalette::Window, QColor(246, 245, 244));
    themeBar.setColor(QPalette::Button, QColor(246, 245, 244));
    themeBar.setColor(QPalette::ButtonText, Qt::black);
    themeBar.setColor(QPalette::WindowText, Qt::black);
    QApplication::setPalette(themeBar, "QMenuBar");
    QApplication::setPalette(themeBar, "QMenu");
    pick("Dark");
    QVERIFY2(bar->palette().color(QPalette::Window).lightness() < 80,
             qPrintable(bar->palette().color(QPalette::Window).name()));
    QVERIFY2(bar->palette().color(QPalette::ButtonText).lightness() > 180,
             qPrintable(bar->palette().color(QPalette::ButtonText).name()));
    QVERIFY2(barLightness() < 80, qPrintable(QString::number(barLightness())));
    for (QMenu* menu : bar->findChildren<QMenu*>())
      QVERIFY2(menu->palette().color(QPalette::Window).lightness() < 80, qPrintable(menu->title()));
    pick("Light");
    QVERIFY2(bar->palette().color(QPalette::Window).lightness() > 180,
             qPrintable(bar->palette().color(QPalette::Window).name()));
    QVERIFY2(barLightness() > 180, qPrintable(QString::number(barLightness())));
    pick("System");
  }

  // Issue 41 item 8: the theme saved as Dark is applied at start, before the window shows.
  void menuBarIsDarkWhenTheWindowStartsDark() {
    fixture_.stop();
    QSettings settings;
    settings.setValue("window/theme", "Dark");
    AppModels models;
    {
      MainWindow window(models, "cpu");
      window.restoreSettings();
      window.resize(900, 700);
      window.show();
      QVERIFY(QTest::qWaitForWindowExposed(&window));
      QMenuBar* bar = window.menuBar();
      const QImage img = bar->grab().toImage();
      const QRect menus = bar->actionGeometry(bar->actions().last());
      const int lightness =
          QColor(img.pixel(std::min(img.width() - 4, menus.right() + 40), img.height() / 2))
              .lightness();
      QVERIFY2(lightness < 80, qPrintable(QString::number(lightness)));
      QVERIFY2(bar->palette().color(QPalette::Window).lightness() < 80,
               qPrintable(bar->palette().color(QPalette::Window).name()));
      settings.setValue("window/theme", "System");
      applyTheme("System");
    }
  }

  // Issue 41 item 2: the panel said HU for any volume. An MR shows its values' unit
  // ("value" for scanner units), a CT HU again.
  void panelUnitsFollowTheVolume() {
    auto* isoLo = fixture_.window->findChild<QDoubleSpinBox*>("isoLo");
    auto* mipLevel = fixture_.window->findChild<QDoubleSpinBox*>("mipLevel");
    auto* width = fixture_.window->findChild<QDoubleSpinBox*>("windowWidth");
    auto* shift = fixture_.window->findChild<QPushButton*>("presetShiftReset");
    QVERIFY(isoLo && mipLevel && width && shift);
    QCOMPARE(isoLo->suffix(), QString(" HU"));  // the phantom is a CT
    QCOMPARE(width->suffix(), QString(" HU"));
    QCOMPARE(shift->text(), QString("+0 HU"));
    Volume mr = makeHeadPhantom(16);
    mr.modality = "MR";
    mr.unit = "MR signal (scanner units)";
    fixture_.models->document.set(std::make_shared<const Volume>(std::move(mr)), "mr");
    QCOMPARE(isoLo->suffix(), QString(" value"));
    QCOMPARE(mipLevel->suffix(), QString(" value"));
    QCOMPARE(width->suffix(), QString(" value"));
    QCOMPARE(shift->text(), QString("+0 value"));
    fixture_.models->document.set(std::make_shared<const Volume>(makeHeadPhantom(16)), "ct");
    QCOMPARE(isoLo->suffix(), QString(" HU"));
    QCOMPARE(shift->text(), QString("+0 HU"));
  }

  // Drawn through the engine's camera: from the patient's left-front (azimuth 45) the L arm
  // comes towards the viewer on the right, drawn bright; R goes away on the left, dimmed.
  // From above-front (elevation 30) S comes towards the viewer, at the top.
  void orientationMarkerFollowsTheCamera() {
    const QColor lr = planeColor(0), si = planeColor(2);
    QImage leftFront = markerImage(45.0, 0.0), rightFront = markerImage(-45.0, 0.0);
    const QPointF l = meanOf(leftFront, lr), r = meanOf(leftFront, lr.darker(170));
    QVERIFY2(l.x() > 0 && r.x() > 0, "marker arms missing");
    QVERIFY2(l.x() > r.x() + 10, qPrintable(QString("%1 %2").arg(l.x()).arg(r.x())));
    QVERIFY(meanOf(rightFront, lr).x() < meanOf(rightFront, lr.darker(170)).x() - 10);
    QImage above = markerImage(0.0, 30.0);
    const QPointF s = meanOf(above, si), i = meanOf(above, si.darker(170));
    QVERIFY2(s.y() > 0 && i.y() > 0, "marker arms missing");
    QVERIFY2(s.y() < i.y() - 10, qPrintable(QString("%1 %2").arg(s.y()).arg(i.y())));
  }
};

QTEST_MAIN(DesktopTest)
#include "desktop_test.moc"
