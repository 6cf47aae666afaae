#pragma once
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
// The tests, by feature: compare_fusion_test.cpp, compare_columns_test.cpp and
// compare_prior_drags_test.cpp; compare_test.cpp holds the fixture.
#include <QObject>
#include <QStringList>
#include <QTemporaryDir>

#include <glm/glm.hpp>

#include "window_fixture.h"

// A turn of DEGREES about the z axis.
glm::dmat3 turnAboutZ(double degrees);

class CompareTest : public QObject {
  Q_OBJECT
  voxray::ui::test::PhantomWindow fixture_;
  QTemporaryDir tmp_;
  QStringList errors_;

 private slots:
  void init();
  void cleanup();
  // compare_fusion_test.cpp
  void fusedSlicePixelHasTheColourMapsColour();
  void fused3DFrameShowsTheOverlay();
  void overlayOpenedWithoutSharedFrameOfReferenceSaysSo();
  void fusionOverlayIsKeptBySessionsAndAMissingOneIsSaid();
  void fourDOverlayAndPriorFollowTheStudysTimeSlider();
  // compare_columns_test.cpp
  void scrollingLeftColumnMovesRightToSamePatientZ();
  void priorAndAlignmentAreKeptBySessions();
  void windowLevelLinkAndSwapAndFlickerKeys();
  // compare_prior_drags_test.cpp
  void dragInStudys3DViewTurnsThePriorsToTheSameCamera();
  void editUndoTakesBackPriorDragsInTheOrderMadeAndSessionsKeepTheLook();
  void movePriorDragsMoveByThePixelSpacingAndTurnByTheSweptAngle();
};
