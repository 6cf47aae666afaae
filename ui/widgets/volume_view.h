#pragma once
// The 3D raycast view: shows the render thread's latest frame and turns the mouse into
// camera, clip-box and light edits on the RenderStateModel. Left-drag rotates, wheel or
// right-drag zooms, middle-drag or Shift+left pans, arrow keys rotate; dragging a clip-box
// face handle moves that face; dragging the sun-shaped handle moves the light. Ctrl+click
// picks a point on the iso surface, or in dvr where the ray's opacity reaches 0.5 (two picks
// make a distance, MeasurementModel::addPick). Alt+left drag (or any left drag in the
// transfer-function mode) shapes what shows: up/down moves it along HU, left/right stretches
// it, with Ctrl up/down scales the opacity (tf_drag.h; iso: the threshold, mip: the window).
#include <memory>
#include <optional>
#include <vector>

#include <QImage>
#include <QWidget>

#include "crosshair_model.h"
#include "measurement_model.h"
#include "render_scheduler.h"
#include "segment_tools.h"
#include "view_projection.h"

namespace voxray::ui {

class VolumeView : public QWidget {
  Q_OBJECT
 public:
  VolumeView(RenderStateModel& state, VolumeDocument& doc, CrosshairModel& crosshair,
             RenderScheduler& scheduler, QWidget* parent = nullptr);
  ~VolumeView() override;

  // Leaves out the patient and study text while an export grabs the view (unless chosen).
  void setStudyTextHidden(bool hidden);
  const QImage& lastFrame() const { return frame_; }
  // What the view says over its image while it has none: "Preparing the 3D renderer…"
  // from the volume's arrival to the first frame (the first start compiles the kernels:
  // seconds on PoCL, issue 41 item 9), or that rendering failed; "" once a frame shows.
  QString note() const;
  bool lastFrameInteractive() const { return frameInteractive_; }
  // What the view says over a frame drawn out of core (issue 38): "Not at full resolution (k
  // of n parts)" while a preview shows, what is off out of core; "" for other frames.
  QString frameNote() const;
  // Where the 3D image is drawn inside the widget, and its projection (for overlays, tests).
  QRect imageRect() const;
  std::optional<ViewProjection> projection() const;
  // The measurements that 3D picks add to and that the view draws (none: no picking).
  void setMeasurements(MeasurementModel* m);
  // With a segment tool chosen, Ctrl+click picks the segment under the cursor (it becomes
  // the tools' segment) instead of a measurement point.
  // With the segment tools' Scissors chosen a left drag draws a lasso; on release it removes
  // from the chosen segment what lies behind it (segment_scissors.h). Modifiers keep their
  // meaning (Shift pans, Ctrl picks, Alt shapes the transfer function).
  void setSegmentation(SegmentationModel* model, SegmentToolModel* tools) {
    segmentation_ = model;
    segmentTools_ = tools;
  }
  // Left drags shape the transfer function instead of turning the volume (View menu).
  void setTransferFunctionDrag(bool on) { tfDragMode_ = on; }

 signals:
  void doubleClicked();
  // A Ctrl+click found no surface: MESSAGE says why (for the status bar).
  void pickMissed(const QString& message);
  // The scissors could not cut (no segment chosen).
  void segmentToolFailed(const QString& message);

 protected:
  void paintEvent(QPaintEvent*) override;
  void resizeEvent(QResizeEvent*) override;
  void mousePressEvent(QMouseEvent*) override;
  void mouseMoveEvent(QMouseEvent*) override;
  void mouseReleaseEvent(QMouseEvent*) override;
  void mouseDoubleClickEvent(QMouseEvent*) override;
  void wheelEvent(QWheelEvent*) override;
  void keyPressEvent(QKeyEvent*) override;

 private:
  enum class Drag { None, Rotate, Pan, Zoom, ClipFace, Light, TransferFunction, Scissors };
  glm::dvec2 toImage(QPointF p) const;

  RenderStateModel& state_;
  VolumeDocument& doc_;
  CrosshairModel& crosshair_;
  RenderScheduler& scheduler_;
  QImage frame_;
  bool frameInteractive_ = false;
  QString resolutionNote_, limitsNote_;  // the frame's (Frame::resolutionNote, limitsNote)
  bool studyTextHidden_ = false;
  bool failed_ = false;  // a render error came before any frame
  Drag drag_ = Drag::None;
  QPointF dragStart_, lastPos_;
  int dragFace_ = -1;
  ClipBox dragStartBox_;
  RenderParams dragStartParams_;  // a transfer-function drag starts from these
  bool tfDragMode_ = false;
  int stateConnection_ = 0, crosshairConnection_ = 0, measureConnection_ = 0;
  MeasurementModel* measurements_ = nullptr;
  SegmentationModel* segmentation_ = nullptr;
  SegmentToolModel* segmentTools_ = nullptr;
  std::vector<QPointF> lasso_;
  bool pickSegment_ = false;  // the pending Ctrl+click picks a segment, not a measurement        //
                              // the scissors' polygon so far (widget pixels)
  std::optional<glm::dvec2> pickAt_;  // the Ctrl+click waiting for its hit frame, 0..1 of the image
  void onPickFrame(const Frame& f);
};

}  // namespace voxray::ui
