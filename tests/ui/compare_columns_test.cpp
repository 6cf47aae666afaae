// Compare's two columns: scrolling the left one moves the right one to the same patient z
// (through a non-trivial alignment), sessions keep the prior and its alignment, W/L follows
// only while its box is ticked, and the swap and flicker keys.
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

void wheel(QWidget* w, int notches) {
  const QPointF at(w->width() / 2.0, w->height() / 2.0);
  QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(w, &e);
}

}  // namespace

void CompareTest::scrollingLeftColumnMovesRightToSamePatientZ() {
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

void CompareTest::priorAndAlignmentAreKeptBySessions() {
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

void CompareTest::windowLevelLinkAndSwapAndFlickerKeys() {
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
