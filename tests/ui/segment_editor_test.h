#pragma once
// The workstation's segment editor (issue 34) driven through the real widgets: the Segments
// dock, the slice views' tools and overlays, undo, the 3D view's mask, export and import, and
// the CLI twin (voxray-cli segment writes the label map the seeded-region click makes).
// The tests, by feature: segment_editor_tools_test.cpp, segment_editor_3d_and_tf_test.cpp and
// segment_editor_list_and_files_test.cpp; segment_editor_test.cpp holds the fixture and the
// README figures.
#include <cstdint>
#include <functional>
#include <string>

#include <QImage>
#include <QObject>
#include <QPoint>
#include <QString>
#include <QStringList>

#include "segment_panel.h"
#include "slice_view.h"
#include "window_fixture.h"

namespace voxray::ui {

// The voxels of S that hold LABEL.
size_t countLabel(const Segmentation& s, uint8_t label);
// FILE's bytes.
std::string readAll(const QString& path);
// Pixels of a frame that are not its background (black).
int litPixels(const QImage& image);

class SegmentEditorTest : public QObject {
  Q_OBJECT
  test::PhantomWindow fixture_;
  QStringList errors_;

  AppModels& models() { return *fixture_.models; }
  SegmentPanel& panel() { return fixture_.window->segments(); }
  SliceView& axial() { return fixture_.window->sliceView(0); }

  void setTool(const std::function<void(SegmentToolSettings&)>& edit);
  // Where in the axial view a voxel's centre is drawn (the nearest whole widget pixel).
  QPoint widgetOf(glm::dvec3 voxel);
  // The voxel position the view takes for a click at P (its own mapping, public parts).
  glm::dvec3 voxelAt(QPoint p);
  uint8_t addSegment();

  // The pixels of AFTER more than 2 levels from BEFORE in a channel, and of those the ones
  // outside where the segment shows (lit in SHOW_A or SHOW_B, grown by one pixel).
  struct SegmentChange {
    int changed = 0, outside = 0, shown = 0;
  };
  static SegmentChange changeWhereTheSegmentShows(const QImage& before, const QImage& after,
                                                  const QImage& showA, const QImage& showB);

  // The README figures' scene: CThead (in HU) in a 1900 x 1040 window, dvr CT-Bone turned by
  // 30 degrees, and a "Skull" segment (threshold 300 ... 3000 HU, largest island) in its colour.
  void openCtheadWithASkullSegment();

 private slots:
  void init();
  void cleanup();
  // segment_editor_tools_test.cpp
  void viewMenuTogglesTheSegmentsDock();
  void paintedDiscChangesItsVoxelsAndUndoRestores();
  void thresholdPreviewCountEqualsTheMask();
  void cliTwinWritesTheSameLabelMap();
  void scissorsLassoInThe3DViewCutsOneUndoStep();
  void ctrlClickIn3DPicksTheSegment();
  void editMenuUndoAndRedoTakeBackAPaintInTheOrderMade();
  // segment_editor_3d_and_tf_test.cpp
  void shownMaskChangesThe3DFrame();
  void surfaceChoiceChangesThe3DFrameAtTheSegment();
  void segmentTfPresetChangesItsPixelsAndUndoRestores();
  void segmentTfEditorDragChangesOnlyThatSegmentsPixels();
  void aNewSegmentOnAFreedLabelStartsWithTheVolumesTf();
  void fromTfTakesTheTransferFunctionsOpaqueRange();
  // segment_editor_list_and_files_test.cpp
  void exportAsksBeforeReplacingAndImportShowsAMismatch();
  void segNrrdImportGivesTheSameVoxels();
  void colourDialogAndTypedOpacityAndCategoryTakeEffect();
  void statisticsFollowEditsAndSaveCsvWritesTheNumbers();
  // segment_editor_test.cpp: the README's figures
  void readmeScreenshot();
  void readmeSurfaceScreenshot();
};

}  // namespace voxray::ui
