// Each column's 3D view and the prior's drags: a drag in the study's 3D view turns the
// prior's to the same camera; Move prior drags move the prior by the dragged millimetres and
// turn it by the swept angle, one undo step each, taken back in the order made; sessions keep
// the look.
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
#include "compare_test.h"
#include "compare_view.h"
#include "fusion_panel.h"
#include "session_state.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "time_panel.h"
#include "voxray/io/phantom_series.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

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

// The angle (degrees) of a rigid transform's rotation, from its trace.
double turnDegrees(const glm::dmat4& m) {
  const double c = (m[0][0] + m[1][1] + m[2][2] - 1.0) / 2.0;
  return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

}  // namespace

void CompareTest::dragInStudys3DViewTurnsThePriorsToTheSameCamera() {
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
void CompareTest::editUndoTakesBackPriorDragsInTheOrderMadeAndSessionsKeepTheLook() {
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
  QTRY_VERIFY_WITH_TIMEOUT(
      c->prior().document.volume() && c->prior().document.volume()->dims == glm::ivec3(48, 48, 32),
      60000);
  QTRY_VERIFY(!c->lookLinked());
  QVERIFY(!c->findChild<QCheckBox*>("compareLinkLook")->isChecked());
  // The saved camera; the link does not follow (no shared Frame of Reference, not aligned).
  QTRY_COMPARE(c->prior().render.params().camera.azimuthDeg, 41.5);
  QCOMPARE(c->prior().render.params().camera.zoom, 1.6);
  QVERIFY(errors_.isEmpty());
}

void CompareTest::movePriorDragsMoveByThePixelSpacingAndTurnByTheSweptAngle() {
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
  const double s = (mv.toSlice(QPointF(1, 0)).x - mv.toSlice(QPointF(0, 0)).x) * prior.spacingMm.x;
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
    const glm::dvec3 p = glm::dvec3(glm::inverse(now) *
                                    glm::dvec4(voxelToPatientMm(study, m.crosshair.centre()), 1.0));
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
