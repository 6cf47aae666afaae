// Fusion and compare through the real widgets (offscreen, issue 36): a fused slice pixel has
// the colour map's colour and the volume's grey shows where the overlay does not reach; an
// overlay opened through the loader without a shared Frame of Reference is shown and the
// status bar says so; in compare mode, scrolling the left column moves the right one to the
// same patient z (through a non-trivial alignment), W/L follows only while its box is ticked,
// and the swap and flicker keys trade and alternate the columns. The 3D view raycasts the
// overlay with the volume (red where the cube is) and drops it when switched off. Each
// column's 3D view: a drag in the study's turns the prior's (a new frame, its camera the
// study's through the alignment); Move prior drags move the prior by the dragged millimetres
// and turn it by the swept angle, one undo step each.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QWheelEvent>

#include "camera_link.h"
#include "compare_view.h"
#include "fusion_panel.h"
#include "session_state.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "time_panel.h"
#include "voxray/io/phantom_series.h"
#include "window_fixture.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

glm::dmat3 turnAboutZ(double degrees) {
  const double a = glm::radians(degrees);
  return glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0),
                    glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
}

// A cube of 1000 (any unit) on a grid of its own: 12 voxels of 4 mm, turned 20 degrees about
// z, centred at CENTREMM.
std::shared_ptr<const Volume> cube(const glm::dvec3& centreMm) {
  Volume o;
  o.dims = glm::ivec3(12);
  o.spacingMm = glm::dvec3(4.0);
  o.direction = turnAboutZ(20.0);
  o.originMm = centreMm - o.direction * (o.spacingMm * 5.5);
  o.unit = "Bq/mL";
  o.voxels.assign(o.voxelCount(), 1000);
  return std::make_shared<const Volume>(std::move(o));
}

// Where patient point P shows in VIEW (an axial view of V through the crosshair's slice).
QPointF widgetAt(const SliceView& view, const Volume& v, const glm::dvec3& p) {
  const glm::dvec3 voxel = glm::inverse(v.direction) * (p - v.originMm) / v.spacingMm;
  const glm::dvec2 s = voxelToSlice(view.axes(), v.dims, voxel);
  return view.toWidget(s.x + 0.5, s.y + 0.5);  // the pixel's centre (slice coords: its corner)
}

// Presses, moves in eight steps with the button held, and releases, as a user's drag.
void drag(QWidget* w, QPointF from, QPointF to, Qt::KeyboardModifiers mods = Qt::NoModifier) {
  auto send = [&](QEvent::Type type, QPointF at, Qt::MouseButton b, Qt::MouseButtons held) {
    QMouseEvent e(type, at, w->mapToGlobal(at), b, held, mods);
    QApplication::sendEvent(w, &e);
  };
  send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
  for (int i = 1; i <= 8; ++i)
    send(QEvent::MouseMove, from + (to - from) * (i / 8.0), Qt::NoButton, Qt::LeftButton);
  send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

// The next sharp (not drag) frame SCHEDULER renders, as VIEW shows it.
QImage nextFullFrame(RenderScheduler& scheduler, VolumeView& view) {
  QSignalSpy spy(&scheduler, &RenderScheduler::frameReady);
  for (int tries = 0; tries < 600; ++tries) {
    while (!spy.isEmpty())
      if (!spy.takeFirst().at(0).value<std::shared_ptr<const Frame>>()->interactive) {
        QCoreApplication::processEvents();
        return view.lastFrame();
      }
    spy.wait(100);
  }
  qFatal("no full-quality frame within 60 s");
}

// The angle (degrees) of a rigid transform's rotation, from its trace.
double turnDegrees(const glm::dmat4& m) {
  const double c = (m[0][0] + m[1][1] + m[2][2] - 1.0) / 2.0;
  return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

void wheel(QWidget* w, int notches) {
  const QPointF at(w->width() / 2.0, w->height() / 2.0);
  QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &e);
}

}  // namespace

class CompareTest : public QObject {
  Q_OBJECT
  voxray::ui::test::PhantomWindow fixture_;
  QTemporaryDir tmp_;
  QStringList errors_;

 private slots:
  void init() {
    QVERIFY(fixture_.start());
    errors_.clear();
    fixture_.window->setErrorSink(
        [this](const QString& t, const QString& m) { errors_ << t + ": " + m; });
  }
  void cleanup() { fixture_.stop(); }

  void fusedSlicePixelHasTheColourMapsColour() {
    AppModels& m = *fixture_.models;
    const Volume& base = *m.document.volume();
    const glm::dvec3 centre = voxelToPatientMm(base, m.crosshair.centre());
    const glm::dvec3 cubeCentre = centre + glm::dvec3(20.0, 16.0, 0.0);  // off the crosshair lines
    m.fusion.setOverlay(cube(cubeCentre), "cube", &base);
    FusionSettings s = m.fusion.settings();
    s.colormap = "rainbow";  // red at and above HI
    s.lo = 0.0;
    s.hi = 500.0;
    s.opacity = 1.0;
    m.fusion.setSettings(s);
    SliceView& axial = fixture_.window->sliceView(0);
    QVERIFY(!axial.fusionOverlayImage().isNull());
    const QImage shot = axial.grab().toImage();
    const QPoint in = widgetAt(axial, base, cubeCentre).toPoint();
    QCOMPARE(QColor(shot.pixel(in)), QColor(255, 0, 0));  // opaque: the map's colour itself
    // 40 mm off the other way the overlay does not reach: the volume's own grey.
    const QPoint out = widgetAt(axial, base, centre - glm::dvec3(40.0, 30.0, 0.0)).toPoint();
    const QColor grey(shot.pixel(out));
    QCOMPARE(grey.red(), grey.green());
    QCOMPARE(grey.green(), grey.blue());
    // Half opacity: halfway between the grey under it and red.
    const QImage plain = [&] {
      s.on = false;
      m.fusion.setSettings(s);
      return axial.grab().toImage();
    }();
    s.on = true;
    s.opacity = 0.5;
    m.fusion.setSettings(s);
    const QColor under(plain.pixel(in)), mixed(axial.grab().toImage().pixel(in));
    QVERIFY2(std::abs(mixed.red() - (under.red() + 255) / 2.0) <= 1.5, qPrintable(mixed.name()));
    QVERIFY2(std::abs(mixed.green() - under.green() / 2.0) <= 1.5, qPrintable(mixed.name()));
    // The cursor readout reads the overlay too.
    QTest::mouseMove(&axial, in);
    axial.grab();  // paints: the readout is the painted one
    QVERIFY2(axial.cursorReadout().contains("overlay 1000 Bq/mL"),
             qPrintable(axial.cursorReadout()));
  }

  void fused3DFrameShowsTheOverlay() {
    AppModels& m = *fixture_.models;
    MainWindow& w = *fixture_.window;
    m.render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; });
    const QImage before = test::waitFullFrame(w);
    // A cube below the head (inferior: -z in LPS), beside it in the default camera's picture,
    // opaque red (rainbow at its end, opacity 1 per step).
    const glm::dvec3 centre = voxelToPatientMm(*m.document.volume(), m.crosshair.centre());
    m.fusion.setOverlay(cube(centre + glm::dvec3(0.0, 0.0, -105.0)), "cube",
                        m.document.volume().get());
    FusionSettings s = m.fusion.settings();
    s.colormap = "rainbow";
    s.lo = 0.0;
    s.hi = 500.0;
    s.opacity = 1.0;
    m.fusion.setSettings(s);
    // A frame asked for before the overlay (the mode change's) may still arrive first: the
    // overlay shows within a few full frames.
    auto redPixels = [](const QImage& img) {
      int n = 0;
      for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
          const QColor c(img.pixel(x, y));
          n += c.red() > 150 && c.green() < 60 && c.blue() < 60;
        }
      return n;
    };
    QImage fused;
    int red = 0;
    for (int frames = 0; frames < 10 && red <= 50; ++frames)
      red = redPixels(fused = test::waitFullFrame(w));
    QVERIFY2(red > 50, qPrintable(QString("%1 red pixels").arg(red)));
    QVERIFY(test::differingPixels(before, fused) >= red);
    // Off again: the frame without it, pixel for pixel.
    s.on = false;
    m.fusion.setSettings(s);
    QImage off = test::waitFullFrame(w);
    for (int frames = 0; frames < 10 && redPixels(off) > 0; ++frames) off = test::waitFullFrame(w);
    QCOMPARE(test::differingPixels(before, off), 0);
  }

  void overlayOpenedWithoutSharedFrameOfReferenceSaysSo() {
    const std::string dir = (tmp_.path() + "/pet").toStdString();
    writePetSpherePhantom(dir, PetSpherePhantom{});
    fixture_.window->openOverlay(dir);
    QTRY_VERIFY_WITH_TIMEOUT(fixture_.models->fusion.overlay() != nullptr, 60000);
    QVERIFY(errors_.isEmpty());
    const QString status = fixture_.window->statusBar()->currentMessage();
    QVERIFY2(status.contains("Frame of Reference"), qPrintable(status));
    QVERIFY(fixture_.window->fusionDock().isVisible());
    QCOMPARE(fixture_.window->fusionPanel().hiBox()->suffix(), QString(" SUVbw"));
    // A window in SUV from the panel reaches the model; a reversed one is refused there.
    fixture_.window->fusionPanel().hiBox()->setValue(4.0);
    QCOMPARE(fixture_.models->fusion.settings().hi, 4.0);
    QCOMPARE(fixture_.models->fusion.settings().lo, 1.0);  // a PET starts at SUV 1 ... 6
    fixture_.window->fusionPanel().loBox()->setValue(5.0);
    QCOMPARE(fixture_.models->fusion.settings().lo, 1.0);
    const QString said = fixture_.window->fusionPanel().findChild<QLabel*>("fusionError")->text();
    QVERIFY2(said.contains("LO must be below HI"), qPrintable(said));
  }

  void scrollingLeftColumnMovesRightToSamePatientZ() {
    AppModels& m = *fixture_.models;
    fixture_.window->setCompareMode(true);
    CompareView* c = fixture_.window->compareView();
    QVERIFY(c && c->isVisible());
    QVERIFY(!fixture_.window->grid().isVisible());
    // The prior: the phantom on a coarser grid (48 voxels for the same 256 mm box).
    c->setPrior(std::make_shared<const Volume>(makeHeadPhantom(48)), "prior");
    QVERIFY(!c->comparison().linked());  // neither names a Frame of Reference
    QVERIFY(c->statusText().contains("not linked until aligned"));
    // The user's alignment: the prior turned 7 degrees about z and shifted.
    glm::dmat4 t(turnAboutZ(7.0));
    t[3] = glm::dvec4(4.0, -3.0, 6.0, 1.0);
    c->comparison().setMovingToFixed(t);
    QVERIFY(c->comparison().linked());
    QTest::qWait(50);
    const Volume& prior = *c->prior().document.volume();
    const Volume& study = *m.document.volume();
    double lastZ = voxelToPatientMm(study, m.crosshair.centre()).z;
    for (int notches : {3, -1, 5, -7}) {
      wheel(&c->fixedView(), notches);
      const glm::dvec3 fixedMm = voxelToPatientMm(study, m.crosshair.centre());
      // The wheel moved the study by NOTCHES slices (4 mm each on the 64-voxel phantom).
      QCOMPARE(fixedMm.z - lastZ, notches * study.spacingMm.z);
      lastZ = fixedMm.z;
      const glm::dvec3 priorMm(
          t * glm::dvec4(voxelToPatientMm(prior, c->prior().crosshair.centre()), 1.0));
      // Within half the prior's slice spacing (it rounds to its own slices; z turns into z).
      QVERIFY2(std::abs(priorMm.z - fixedMm.z) <= 0.5 * prior.spacingMm.z + 1e-9,
               qPrintable(QString("z %1 vs %2").arg(priorMm.z).arg(fixedMm.z)));
    }
    // Zoom follows the other column.
    QWheelEvent zoom(QPointF(50, 50), c->fixedView().mapToGlobal(QPointF(50, 50)), QPoint(),
                     QPoint(0, 240), Qt::NoButton, Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&c->fixedView(), &zoom);
    QVERIFY(c->fixedView().zoom() > 1.0);
    QCOMPARE(c->movingView().zoom(), c->fixedView().zoom());
  }

  void priorAndAlignmentAreKeptBySessions() {
    AppModels& m = *fixture_.models;
    MainWindow& w = *fixture_.window;
    const std::string dir = (tmp_.path() + "/prior-pet").toStdString();
    writePetSpherePhantom(dir, PetSpherePhantom{});
    w.openPrior(dir);
    QTRY_VERIFY_WITH_TIMEOUT(w.compareView() && w.compareView()->hasPrior(), 60000);
    QVERIFY(w.compareView()->isVisible());
    glm::dmat4 t(turnAboutZ(-4.0));
    t[3] = glm::dvec4(1.5, 2.0, -3.0, 1.0);
    w.compareView()->comparison().setMovingToFixed(t);
    const Session saved = sessionFromModels(m, {128, 96}, "grid");
    QVERIFY(saved.comparison);
    QCOMPARE(saved.comparison->priorPath, dir);
    QVERIFY(saved.comparison->movingToFixed && *saved.comparison->movingToFixed == t);
    // Reopened: the session's state is applied, then the window opens the prior again with
    // the session's alignment (not the one on screen now).
    w.compareView()->comparison().clearAlignment();
    applySession(m, saved);
    emit w.sessions().sessionShown();
    QTRY_VERIFY_WITH_TIMEOUT(w.compareView()->comparison().aligned(), 60000);
    QVERIFY(w.compareView()->comparison().movingToFixed() == t);
    QVERIFY(errors_.isEmpty());
  }

  void dragInStudys3DViewTurnsThePriorsToTheSameCamera() {
    AppModels& m = *fixture_.models;
    fixture_.window->setCompareMode(true);
    CompareView* c = fixture_.window->compareView();
    c->setPrior(std::make_shared<const Volume>(makeHeadPhantom(48)), "prior");
    // The prior turned 7 degrees about z and shifted onto the study.
    glm::dmat4 t(turnAboutZ(7.0));
    t[3] = glm::dvec4(4.0, -3.0, 6.0, 1.0);
    c->comparison().setMovingToFixed(t);
    const QImage before = test::settledFrame(c->priorScheduler(), c->moving3dView());
    QVERIFY(!before.isNull());
    const double azimuth = m.render.params().camera.azimuthDeg;
    // A 50-pixel left drag in the study's 3D view, clear of the clip and light handles.
    VolumeView& a = c->fixed3dView();
    const QPointF from(a.width() * 0.25, a.height() * 0.25);
    drag(&a, from, from + QPointF(50.0, 0.0));
    // The study turned 20 degrees (0.4 per pixel, the camera against the mouse) ...
    const CameraParams& ca = m.render.params().camera;
    const CameraParams& cb = c->prior().render.params().camera;
    QVERIFY2(std::abs(ca.azimuthDeg - (azimuth - 20.0)) < 1e-9,
             qPrintable(QString::number(ca.azimuthDeg)));
    // ... and the prior's camera is the study's through the alignment: 7 degrees less azimuth
    // (its patient is turned 7 degrees the other way), the same elevation and zoom, its eye
    // on the study's eye mapped into the prior (1e-9 deg/mm: rounding only).
    QVERIFY2(std::abs(std::remainder(cb.azimuthDeg - (ca.azimuthDeg - 7.0), 360.0)) < 1e-9,
             qPrintable(QString("%1 vs %2").arg(cb.azimuthDeg).arg(ca.azimuthDeg)));
    QVERIFY(std::abs(cb.elevationDeg - ca.elevationDeg) < 1e-9);
    QCOMPARE(cb.zoom, ca.zoom);
    const PatientView va = patientView(ca, c->comparison().fixed());
    const PatientView vb = patientView(cb, c->comparison().moving());
    const glm::dvec3 eye(glm::inverse(t) * glm::dvec4(va.eyeMm, 1.0));
    QVERIFY(glm::length(vb.eyeMm - eye) < 1e-9);
    // The prior's 3D view shows the turn: a new frame, much of it changed.
    const QImage after = test::settledFrame(c->priorScheduler(), c->moving3dView());
    const int changed = test::differingPixels(before, after);
    QVERIFY2(changed > before.width() * before.height() / 20,
             qPrintable(QString("%1 pixels changed").arg(changed)));
    QCOMPARE(c->prior().render.params().preset, m.render.params().preset);  // the same look
    // Back to the four views: the prior's camera rests while the study turns (no frames for a
    // hidden view); compare again: it follows from the study's camera at once.
    const double priorAzimuth = cb.azimuthDeg;
    fixture_.window->setCompareMode(false);
    m.render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg += 15.0; });
    QCOMPARE(c->prior().render.params().camera.azimuthDeg, priorAzimuth);
    fixture_.window->setCompareMode(true);
    QVERIFY(std::abs(std::remainder(c->prior().render.params().camera.azimuthDeg -
                                        (m.render.params().camera.azimuthDeg - 7.0),
                                    360.0)) < 1e-9);
  }

  // Issue 36 leftovers: a Move prior drag is one step of Edit → Undo, in the order made with
  // the view's edits (the compare view's own Undo move buttons follow); the Link 3D look box
  // and the prior's 3D camera are kept by sessions.
  void editUndoTakesBackPriorDragsInTheOrderMadeAndSessionsKeepTheLook() {
    AppModels& m = *fixture_.models;
    MainWindow& w = *fixture_.window;
    w.setCompareMode(true);
    CompareView* c = w.compareView();
    c->setPrior(std::make_shared<const Volume>(makeHeadPhantom(48)), "prior");
    m.comparison = Session::Comparison{"/somewhere/prior", std::nullopt};  // as openPrior sets
    glm::dmat4 t0(turnAboutZ(5.0));
    t0[3] = glm::dvec4(2.0, 1.0, -4.0, 1.0);
    c->comparison().setMovingToFixed(t0);
    QAction* undo = w.findChild<QAction*>("editUndo");
    QAction* redo = w.findChild<QAction*>("editRedo");
    QVERIFY(undo && redo);
    const WindowLevel start = m.windowLevel.value();
    m.windowLevel.set(WindowLevel{350.0, 45.0});  // a view edit before the drag
    c->findChild<QPushButton*>("compareMovePrior")->click();
    SliceView& mv = c->movingView();
    const QPointF from(mv.width() * 0.3, mv.height() * 0.4);
    drag(&mv, from, from + QPointF(40.0, 0.0));
    const glm::dmat4 t1 = c->comparison().movingToFixed();
    QVERIFY(t1 != t0);
    m.windowLevel.set(WindowLevel{1500.0, -600.0});  // and one after it
    QCOMPARE(undo->toolTip(), QString("Undo view change"));
    undo->trigger();
    QCOMPARE(m.windowLevel.value().width, 350.0);
    QVERIFY(c->comparison().movingToFixed() == t1);  // the prior stays where it was dragged
    QCOMPARE(undo->toolTip(), QString("Undo move prior"));
    undo->trigger();
    QVERIFY(c->comparison().movingToFixed() == t0);  // the whole drag is one step
    QCOMPARE(m.windowLevel.value().width, 350.0);
    QVERIFY(!c->findChild<QPushButton*>("compareUndoMove")->isEnabled());
    QVERIFY(c->findChild<QPushButton*>("compareRedoMove")->isEnabled());
    undo->trigger();
    QCOMPARE(m.windowLevel.value().width, start.width);
    redo->trigger();
    redo->trigger();
    QVERIFY(c->comparison().movingToFixed() == t1);
    QCOMPARE(m.windowLevel.value().width, 350.0);
    // The compare view's own Undo move: Edit → Redo then redoes that drag.
    c->findChild<QPushButton*>("compareUndoMove")->click();
    QVERIFY(c->comparison().movingToFixed() == t0);
    QCOMPARE(redo->toolTip(), QString("Redo move prior"));
    redo->trigger();
    QVERIFY(c->comparison().movingToFixed() == t1);

    // Sessions: Link 3D look unticked and the prior's camera as it is now.
    c->setMovePrior(false);
    c->findChild<QCheckBox*>("compareLinkLook")->setChecked(false);
    c->prior().render.update(kCamera, [](RenderParams& p) {
      p.camera.azimuthDeg = 41.5;
      p.camera.zoom = 1.6;
    });
    const CameraParams priorCamera = c->prior().render.params().camera;
    const Session saved = sessionFromModels(m, {128, 96}, "grid");
    QVERIFY(saved.comparison && !saved.comparison->linkLook);
    QVERIFY(saved.comparison->priorCamera);
    QCOMPARE(saved.comparison->priorCamera->azimuthDeg, priorCamera.azimuthDeg);
    QCOMPARE(saved.comparison->priorCamera->zoom, 1.6);
    // Through the file and back, then reopened by the window (the prior loads again).
    const QString file = tmp_.path() + "/look.json";
    const std::string dir = (tmp_.path() + "/prior-look").toStdString();
    writePetSpherePhantom(dir, PetSpherePhantom{});
    Session withFile = saved;
    withFile.comparison->priorPath = dir;
    writeSessionFile(file.toStdString(), withFile, true);
    const Session read = readSessionFile(file.toStdString()).session;
    c->findChild<QCheckBox*>("compareLinkLook")->setChecked(true);
    applySession(m, read);
    emit w.sessions().sessionShown();
    QTRY_VERIFY_WITH_TIMEOUT(c->prior().document.volume() &&
                                 c->prior().document.volume()->dims == glm::ivec3(48, 48, 32),
                             60000);
    QTRY_VERIFY(!c->lookLinked());
    QVERIFY(!c->findChild<QCheckBox*>("compareLinkLook")->isChecked());
    // The saved camera; the link does not follow (no shared Frame of Reference, not aligned).
    QTRY_COMPARE(c->prior().render.params().camera.azimuthDeg, 41.5);
    QCOMPARE(c->prior().render.params().camera.zoom, 1.6);
    QVERIFY(errors_.isEmpty());
  }

  void movePriorDragsMoveByThePixelSpacingAndTurnByTheSweptAngle() {
    AppModels& m = *fixture_.models;
    fixture_.window->setCompareMode(true);
    CompareView* c = fixture_.window->compareView();
    c->setPrior(std::make_shared<const Volume>(makeHeadPhantom(48)), "prior");
    m.comparison = Session::Comparison{"/somewhere/prior", std::nullopt};  // as openPrior sets
    glm::dmat4 t0(turnAboutZ(5.0));
    t0[3] = glm::dvec4(2.0, 1.0, -4.0, 1.0);
    c->comparison().setMovingToFixed(t0);
    c->findChild<QPushButton*>("compareMovePrior")->click();
    QVERIFY(c->movePrior());
    const Volume& prior = *c->prior().document.volume();
    const Volume& study = *m.document.volume();
    // In the prior's column: 40 pixels to the right at its pixel spacing S (mm per widget
    // pixel: the slice's voxels over the view's pixels).
    SliceView& mv = c->movingView();
    const double s =
        (mv.toSlice(QPointF(1, 0)).x - mv.toSlice(QPointF(0, 0)).x) * prior.spacingMm.x;
    const QPointF from(mv.width() * 0.3, mv.height() * 0.4);
    drag(&mv, from, from + QPointF(40.0, 0.0));
    const glm::dmat4 t1 = c->comparison().movingToFixed();
    const glm::dvec3 moved = glm::dvec3(t1[3]) - glm::dvec3(t0[3]);
    // N * s mm along the prior's screen right (patient left, +x), turned into the study's
    // coordinates by the alignment: exact to rounding (1e-9 mm).
    QVERIFY2(std::abs(glm::length(moved) - 40.0 * s) < 1e-9,
             qPrintable(QString("%1 mm vs %2").arg(glm::length(moved)).arg(40.0 * s)));
    QVERIFY(glm::length(moved - glm::dmat3(t0) * glm::dvec3(40.0 * s, 0, 0)) < 1e-9);
    QCOMPARE(c->moveHistory().undoCount(), size_t(1));
    // The linked crosshair maps the same point through the new transform (half a voxel).
    auto crosshairError = [&] {
      const glm::dmat4 now = c->comparison().movingToFixed();
      const glm::dvec3 p = glm::dvec3(
          glm::inverse(now) * glm::dvec4(voxelToPatientMm(study, m.crosshair.centre()), 1.0));
      const glm::dvec3 d =
          glm::abs(c->comparison().moving().voxelOf(p) - c->prior().crosshair.centre());
      return std::max({d.x, d.y, d.z});
    };
    QVERIFY2(crosshairError() <= 0.5 + 1e-9, qPrintable(QString::number(crosshairError())));
    // In the study's column, Shift+drag from 30 px right of the crosshair to 30 px below it:
    // a quarter turn clockwise on screen, about the crosshair.
    SliceView& fv = c->fixedView();
    const glm::dvec2 sc = voxelToSlice(fv.axes(), study.dims, m.crosshair.centre());
    const QPointF pivot = fv.toWidget(sc.x, sc.y);
    const QPointF a = pivot + QPointF(30.0, 0.0), b = pivot + QPointF(0.0, 30.0);
    const double swept = glm::degrees(std::atan2(b.y() - pivot.y(), b.x() - pivot.x()) -
                                      std::atan2(a.y() - pivot.y(), a.x() - pivot.x()));
    QVERIFY(std::abs(swept - 90.0) < 1e-9);
    drag(&fv, a, b, Qt::ShiftModifier);
    const glm::dmat4 t2 = c->comparison().movingToFixed();
    QVERIFY2(std::abs(turnDegrees(t2 * glm::inverse(t1)) - swept) < 1e-9,
             qPrintable(QString::number(turnDegrees(t2 * glm::inverse(t1)))));
    const glm::dvec3 pivotMm = voxelToPatientMm(study, m.crosshair.centre());
    QVERIFY(glm::length(glm::dvec3(t2 * glm::inverse(t1) * glm::dvec4(pivotMm, 1.0)) - pivotMm) <
            1e-9);
    QVERIFY(crosshairError() <= 0.5 + 1e-9);
    QVERIFY(c->comparison().linked());
    // The session keeps the dragged transform; each drag was one undo step.
    QVERIFY(m.comparison && m.comparison->movingToFixed && *m.comparison->movingToFixed == t2);
    QCOMPARE(c->moveHistory().undoCount(), size_t(2));
    c->findChild<QPushButton*>("compareUndoMove")->click();
    QVERIFY(c->comparison().movingToFixed() == t1);
    c->findChild<QPushButton*>("compareUndoMove")->click();
    QVERIFY(c->comparison().movingToFixed() == t0);
    QVERIFY(!c->findChild<QPushButton*>("compareUndoMove")->isEnabled());
    c->findChild<QPushButton*>("compareRedoMove")->click();
    QVERIFY(c->comparison().movingToFixed() == t1);
    // The keys, with the focus in a column: Ctrl+Shift+Z redoes the turn, Ctrl+Z takes it
    // back (in Move prior mode they are the prior's, not the Edit menu's, which has a view
    // change to take back).
    m.render.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg += 10.0; });
    QVERIFY(fixture_.window->findChild<QAction*>("editUndo")->isEnabled());
    const double azimuth = m.render.params().camera.azimuthDeg;
    mv.setFocus();
    QTest::keyClick(&mv, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(c->comparison().movingToFixed() == t2);
    QTest::keyClick(&mv, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(c->comparison().movingToFixed() == t1);
    QCOMPARE(m.render.params().camera.azimuthDeg, azimuth);
    // Move prior off: a left drag moves the crosshair again, not the prior.
    c->setFocus();
    QTest::keyClick(c, Qt::Key_M);
    QVERIFY(!c->movePrior());
    drag(&mv, from, from + QPointF(0.0, 25.0));
    QVERIFY(c->comparison().movingToFixed() == t1);
    mv.setFocus();
    QTest::keyClick(&mv, Qt::Key_Z, Qt::ControlModifier);  // the Edit menu's: not the prior's
    QVERIFY(c->comparison().movingToFixed() == t1);
    QVERIFY(m.render.params().camera.azimuthDeg != azimuth);  // the view change taken back
  }

  // The overlay's file and look go into the session: reopened, the PET overlay comes back with
  // its SUV window, map, opacity and off state; with its file gone, the session still opens
  // (the study's window) and says the overlay is missing.
  void fusionOverlayIsKeptBySessionsAndAMissingOneIsSaid() {
    AppModels& m = *fixture_.models;
    MainWindow& w = *fixture_.window;
    const std::string pet = (tmp_.path() + "/fused-pet").toStdString();
    writePetSpherePhantom(pet, PetSpherePhantom{});
    w.openOverlay(pet);
    QTRY_VERIFY_WITH_TIMEOUT(m.fusion.overlay() != nullptr, 60000);
    QCOMPARE(QString::fromStdString(m.fusion.sourcePath()), QString::fromStdString(pet));
    FusionSettings look = m.fusion.settings();
    look.colormap = "rainbow";
    look.lo = 2.25;  // SUVbw
    look.hi = 5.5;
    look.opacity = 0.3;
    look.on = false;
    m.fusion.setSettings(look);
    m.windowLevel.set({700.0, 60.0});
    SessionActions& sessions = w.sessions();
    QStringList told;
    sessions.tell = [&](const QString& t, const QString& text) { told << t + ": " + text; };
    const QString file = tmp_.path() + "/fused.json";
    QVERIFY(sessions.saveTo(file));
    m.fusion.clear();
    m.windowLevel.set({100.0, 0.0});
    QSignalSpy shown(&sessions, &SessionActions::sessionShown);
    sessions.openFile(file.toStdString());
    QVERIFY(shown.wait(60000));
    QTRY_VERIFY_WITH_TIMEOUT(m.fusion.overlay() != nullptr && m.fusion.settings() == look, 60000);
    QCOMPARE(m.fusion.settings().lo, 2.25);
    QVERIFY(!m.fusion.active());  // saved off
    QCOMPARE(w.fusionPanel().colormapBox()->currentText(), QString("rainbow"));
    QCOMPARE(w.fusionPanel().loBox()->value(), 2.25);
    QCOMPARE(m.windowLevel.value().width, 700.0);
    QVERIFY2(told.isEmpty(), qPrintable(told.join('\n')));
    // The overlay's folder gone: the rest of the session opens, the message names the place.
    QDir(QString::fromStdString(pet)).removeRecursively();
    m.windowLevel.set({100.0, 0.0});
    sessions.openFile(file.toStdString());
    QVERIFY(shown.wait(60000));
    QCOMPARE(m.windowLevel.value().width, 700.0);
    QVERIFY(m.fusion.overlay() == nullptr);
    QCOMPARE(told.size(), 1);
    QVERIFY2(told[0].contains("its data is missing (not at " + QString::fromStdString(pet)) &&
                 told[0].contains("The session opened without its fusion overlay"),
             qPrintable(told[0]));
    QVERIFY(errors_.isEmpty());
  }

  // A 4D overlay and a 4D prior beside a 4D study (the beating sphere: radius 12 + 4 sin(2 pi
  // t / phases) mm): with as many phases they follow the study's time slider, the panel's and
  // the bar's time boxes saying so; with five phases beside ten they keep the time point
  // chosen in their box, and a session keeps it.
  void fourDOverlayAndPriorFollowTheStudysTimeSlider() {
    AppModels& m = *fixture_.models;
    MainWindow& w = *fixture_.window;
    BeatingSpherePhantom p;
    p.dims = {32, 32, 16};
    p.radiusMm = 12.0;
    p.amplitudeMm = 4.0;
    const QString dir = tmp_.path();
    writeBeatingSpherePhantom((dir + "/study").toStdString(), p);
    writeBeatingSpherePhantom((dir + "/ten").toStdString(), p);
    BeatingSpherePhantom five = p;
    five.phases = 5;
    writeBeatingSpherePhantom((dir + "/five").toStdString(), five);
    QSignalSpy shown(&w, &MainWindow::volumeShown);
    w.open((dir + "/study").toStdString(), {});
    QVERIFY(shown.wait(60000));
    QCOMPARE(m.document.timePoints(), 10);
    // Voxel (25, 15, 7): 14.35 mm from the centre, inside at phases 2 and 3 (15.8 mm), outside
    // at 0 (12 mm) and 7 (8.2 mm).
    const Volume& v0 = *m.document.volume();
    const glm::dvec3 probe = v0.originMm + v0.direction * (glm::dvec3(25, 15, 7) * v0.spacingMm);
    w.openOverlay((dir + "/ten").toStdString());
    QTRY_VERIFY_WITH_TIMEOUT(m.fusion.series().size() == 10, 60000);
    QSpinBox* box = w.fusionPanel().timeBox();
    QVERIFY(!box->isEnabled());
    QCOMPARE(box->suffix(), QString(" (follows the study)"));
    QSlider* slider = w.timePanel().slider();
    for (int t : {2, 7, 3, 0}) {
      slider->setValue(t);
      QCOMPARE(m.document.timePoint(), t);
      QCOMPARE(m.fusion.overlay()->timePoint, t);
      QCOMPARE(box->value(), t);
      const bool inside = t == 2 || t == 3;
      QCOMPARE(QString::fromStdString(fusionProbeText(*m.fusion.overlay(), probe)),
               QString(inside ? "overlay 300 HU" : "overlay -50 HU"));
    }
    // Five phases over ten: its own time point, chosen in the panel.
    w.openOverlay((dir + "/five").toStdString());
    QTRY_VERIFY_WITH_TIMEOUT(m.fusion.series().size() == 5, 60000);
    QVERIFY(box->isEnabled());
    QCOMPARE(box->suffix(), QString(" of 0-4"));
    slider->setValue(6);
    QCOMPARE(m.fusion.overlay()->timePoint, 0);
    box->setValue(1);  // radius 12 + 4 sin 72 degrees = 15.8 mm: the probe is inside
    QCOMPARE(m.fusion.overlay()->timePoint, 1);
    QCOMPARE(QString::fromStdString(fusionProbeText(*m.fusion.overlay(), probe)),
             QString("overlay 300 HU"));
    slider->setValue(7);
    QCOMPARE(m.fusion.overlay()->timePoint, 1);
    // The prior: ten phases follow the slider; five keep the bar's choice.
    w.openPrior((dir + "/ten").toStdString());
    QTRY_VERIFY_WITH_TIMEOUT(w.compareView() && w.compareView()->hasPrior(), 60000);
    CompareView& c = *w.compareView();
    QVERIFY(c.priorTimeBox()->isVisible());
    QVERIFY(!c.priorTimeBox()->isEnabled());
    QCOMPARE(c.prior().document.timePoint(), 7);  // the study's, at once
    slider->setValue(4);
    QCOMPARE(c.prior().document.timePoint(), 4);
    QCOMPARE(c.priorTimeBox()->value(), 4);
    w.openPrior((dir + "/five").toStdString());
    QTRY_VERIFY_WITH_TIMEOUT(c.prior().document.timePoints() == 5, 60000);
    QVERIFY(c.priorTimeBox()->isEnabled());
    QCOMPARE(c.prior().document.timePoint(), 0);
    c.priorTimeBox()->setValue(3);
    QCOMPARE(c.prior().document.timePoint(), 3);
    slider->setValue(9);
    QCOMPARE(c.prior().document.timePoint(), 3);
    const Session saved = sessionFromModels(m, {128, 96}, "grid");
    QVERIFY(saved.fusion && saved.comparison);
    QCOMPARE(saved.fusion->timePoint, 1);
    QCOMPARE(saved.comparison->priorTimePoint, 3);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("; ")));
  }

  void windowLevelLinkAndSwapAndFlickerKeys() {
    AppModels& m = *fixture_.models;
    fixture_.window->setCompareMode(true);
    CompareView* c = fixture_.window->compareView();
    c->setPrior(std::make_shared<const Volume>(makeHeadPhantom(48)), "prior");
    m.windowLevel.set({1200.0, 250.0});
    QCOMPARE(c->prior().windowLevel.value().width, 1200.0);
    c->findChild<QCheckBox*>("compareLinkWl")->setChecked(false);
    m.windowLevel.set({300.0, 30.0});
    QCOMPARE(c->prior().windowLevel.value().width, 1200.0);
    c->fixedView().setFocus();
    QTest::keyClick(&c->fixedView(), Qt::Key_X);
    QVERIFY(c->swapped());
    QVERIFY(c->movingView().mapTo(c, QPoint()).x() < c->fixedView().mapTo(c, QPoint()).x());
    QTest::keyClick(&c->fixedView(), Qt::Key_F);
    QCOMPARE(c->shownColumns(), 1);
    QVERIFY(!c->movingView().isVisible());
    c->movingView().setFocus();
    QTest::keyClick(&c->fixedView(), Qt::Key_F);
    QCOMPARE(c->shownColumns(), 2);
    QVERIFY(!c->fixedView().isVisible());
    QVERIFY(c->movingView().isVisible());
    QTest::keyClick(&c->movingView(), Qt::Key_B);
    QCOMPARE(c->shownColumns(), 0);
    // Point pairs: two are refused with the message in the status line.
    c->addPairAtCrosshairs();
    c->addPairAtCrosshairs();
    QVERIFY(!c->align());
    QVERIFY2(c->statusText().contains("at least three"), qPrintable(c->statusText()));
    c->findChild<QPushButton*>("compareClose")->click();
    QVERIFY(!c->isVisible());
    QVERIFY(fixture_.window->grid().isVisible());
  }
};

QTEST_MAIN(CompareTest)
#include "compare_test.moc"
