#pragma once
// One slice view (axial, coronal or sagittal) bound to the shared crosshair, window/level
// and render-state models. Left click/drag moves the crosshair (or a clip-box edge when
// grabbed; or, on a round handle near a crosshair line's end, turns the other two planes:
// oblique MPR), right-drag changes window/level, middle-drag pans, wheel or arrow keys
// scroll slices, Ctrl+wheel zooms, double-click maximises. With a measuring tool chosen
// (MeasurementModel::tool) a left drag draws a distance, ellipse or rectangle, an angle takes
// a drag for its first arm and a click (or drag) for its end; a press on a handle drags that
// point in any mode; Del removes the selected measurement. Measurements live in the
// acquisition planes: a turned or slab view neither shows nor takes them. With the Text tool a
// click opens a line edit there (Return adds the text, Esc drops it); with the Arrow tool a
// drag draws an arrow, its head at the press and its tail at the release (annotation_model.h);
// Del removes the selected annotation.
#include <optional>

#include <QImage>
#include <QPointer>
#include <QWidget>

#include "annotation_model.h"
#include "crosshair_model.h"
#include "fusion.h"
#include "measurement_model.h"
#include "render_state_model.h"
#include "segment_tools.h"
#include "segmentation_model.h"
#include "slab_render.h"
#include "slice_geometry.h"
#include "slice_overlay.h"
#include "volume_document.h"
#include "window_level.h"

namespace voxray::ui {

class SliceView : public QWidget {
  Q_OBJECT
 public:
  SliceView(Orientation o, VolumeDocument& doc, CrosshairModel& crosshair, WindowLevelModel& wl,
            RenderStateModel& state, QWidget* parent = nullptr);
  ~SliceView() override;

  Orientation orientation() const { return orientation_; }
  const SliceAxes& axes() const { return axes_; }
  // W/L applied, square pixels of the finer in-plane spacing (renderSlice; renderPlane of
  // viewPlane when turned or a slab). A slab renders in the background (SlabRenderer): until
  // it arrives the view shows the last slab image, or the thin slice when it has none.
  const QImage& sliceImage() const { return image_; }
  bool slabPending() const { return wanted_.has_value(); }
  // The cursor readout as last painted ("6.607 SUVbw  [24, 24, 16]" and the position);
  // empty while the cursor is outside the view.
  const QString& cursorReadout() const { return cursorReadout_; }
  // The crosshair's two lines on screen and the handles that turn them (widget pixels).
  std::array<glm::dvec2, 2> crosshairTraces() const;
  std::array<QPointF, 4> rotationHandles() const;
  // Widget position of slice coordinates (u, v: voxel units, slice_geometry.h) and back.
  QPointF toWidget(double u, double v) const;
  glm::dvec2 toSlice(QPointF widget) const;
  // Hides the cursor readout and file name (screenshots carry no data unless asked).
  void setAnnotations(bool on);
  // Leaves out the patient and study text while an export grabs the view (unless chosen).
  void setStudyTextHidden(bool hidden);
  // The measurements to draw and edit (none: the view measures nothing).
  void setMeasurements(MeasurementModel* m);
  // The text and arrow annotations to draw and take (none: the view annotates nothing). They
  // follow the measurements' tool and, in exports, their "show in exports" choice.
  void setAnnotationModel(AnnotationModel* a);
  // The line edit a Text click opened, while it is open (tests type into it).
  QWidget* annotationEditor() const { return textEdit_; }
  // While exporting, measurements show only when the user asked for them in exports.
  void setExporting(bool on);
  // The export without overlays (issue 41): the slice as rendered, one pixel per sample of
  // its plane (W/L applied; a slab's projection), with no crosshair, handles, border, text,
  // measurements or annotations; with LAYERS the fused overlay and the segments over it, as
  // the view blends them. Empty while no slice is shown.
  QImage cleanImage(bool layers) const;
  // The segmentation to draw (each visible segment filled and outlined, on every plane: the
  // overlay takes each pixel's voxel) and the tools that edit it: with Paint or Erase a left
  // press and drag paints (one undo step), with Seed a left click fills the connected region,
  // with Threshold the range's voxels on this plane are previewed. Ctrl or Shift with the
  // press leaves the tools out (the crosshair or measurement as without them).
  void setSegmentation(SegmentationModel* model, SegmentToolModel* tools);
  // The segments' overlay and the threshold preview as drawn (the image's size; transparent
  // where nothing is), and the preview's voxels in this view's slice.
  const QImage& segmentOverlayImage() const { return segmentOverlay_; }
  const QImage& thresholdPreviewImage() const { return previewOverlay_; }
  size_t thresholdPreviewVoxels() const;
  // Fusion (issue 36): the overlay volume drawn over the slice through its own geometry, in
  // its colour map (none: no overlay). The overlay as drawn: the image's size, straight alpha.
  void setFusion(FusionModel* fusion);
  const QImage& fusionOverlayImage() const { return fusionOverlay_; }
  // Zoom (1: the slice fits the view); Ctrl+wheel changes it and says so (compare links it).
  double zoom() const { return zoom_; }
  void setZoom(double zoom);

 signals:
  void doubleClicked();
  // A clip-edge drag moved the box (the 3D view should render cheap drag frames), and ended.
  void clipDragged();
  void clipDragEnded();
  // A slab image rendered in the background is now shown (slabPending() is false).
  void slabShown();
  // A segment tool could not do what was asked (no segment chosen, a seed outside the range).
  void segmentToolFailed(const QString& message);
  void zoomChanged(double zoom);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent*) override;
  void mouseMoveEvent(QMouseEvent*) override;
  void mouseReleaseEvent(QMouseEvent*) override;
  void mouseDoubleClickEvent(QMouseEvent*) override;
  void wheelEvent(QWheelEvent*) override;
  void keyPressEvent(QKeyEvent*) override;
  void leaveEvent(QEvent*) override;

 private:
  enum class Drag { None, Crosshair, ClipEdge, WindowLevel, Pan, Handle, Rotate, Brush, Arrow };
  void rebuild();  // new volume, slice or window: redraw the slice image
  void slabArrived(Image image);
  QRectF sliceRect() const;
  int pickClipEdge(QPointF widget) const;  // face number, or -1
  bool onRotationHandle(QPointF widget) const;
  void paintOverlay(QPainter& p);
  QPointF voxelToWidget(const glm::dvec3& voxel) const;
  glm::dvec3 widgetToVoxel(QPointF widget) const;  // on this view's slice, clamped into the box
  bool pressMeasure(QPointF widget);
  bool pressAnnotation(QPointF widget);  // true: the Text or Arrow tool took the press
  void finishText(QPointF at, const QString& text);
  QPointF mmToWidget(const glm::dvec3& patientMm) const;
  glm::dvec3 widgetToMm(QPointF widget) const;  // on this view's slice, in the volume's box
  bool pressSegmentTool(QPointF widget);        // true: a paint, erase or seed tool took the press
  void brushAt(QPointF widget);
  glm::dvec3 toolVoxel(QPointF widget) const;  // the voxel position under the cursor
  void refreshFusion(bool force = false);      // fusionOverlay_ for shown_'s plane
  void refreshSegmentOverlay();                // true: the press grabbed or started a measurement
  // Measurements are drawn and taken in the acquisition planes only: not on a turned view or
  // a slab (their points and ROI pixels are index-plane ones).
  bool measurable() const;

  Orientation orientation_;
  VolumeDocument& doc_;
  CrosshairModel& crosshair_;
  WindowLevelModel& wl_;
  RenderStateModel& state_;
  SliceAxes axes_;
  QImage image_;
  // What image_ shows of the document's volume; none after a document change.
  struct Shown {
    PlaneGrid plane;
    Slab slab;
    WindowLevel wl;
    Interp interp;
    bool sameAs(const Shown& o) const {
      return plane.originMm == o.plane.originMm && plane.uDir == o.plane.uDir &&
             plane.vDir == o.plane.vDir && plane.spacingMm == o.plane.spacingMm &&
             plane.size == o.plane.size && slab.thicknessMm == o.slab.thicknessMm &&
             slab.mode == o.slab.mode && wl.width == o.wl.width && wl.level == o.wl.level &&
             interp == o.interp;
    }
  };
  std::optional<Shown> shown_;
  std::optional<Shown> wanted_;  // the slab image asked of slabs_ and not yet shown
  double zoom_ = 1.0;
  QPointF pan_;
  Drag drag_ = Drag::None;
  int dragFace_ = -1;
  QPointF lastPos_, dragStart_;
  // The crosshair before the first of the left presses that may yet make a double-click,
  // and when the last of them came (event timestamps, ms).
  struct ClickChain {
    glm::dvec3 before;
    ulong at = 0;
  };
  std::optional<ClickChain> clickChain_;
  WindowLevel dragStartWl_;
  QPointF hover_{-1, -1};
  bool annotations_ = true;
  bool studyTextHidden_ = false;
  MeasurementModel* measurements_ = nullptr;
  bool exporting_ = false;
  int dragId_ = 0, dragIndex_ = 0;
  int angleToFinish_ = 0;  // an angle with its first arm drawn, waiting for its end point
  int measureConnection_ = 0;
  AnnotationModel* annotationModel_ = nullptr;
  int annotationConnection_ = 0;
  glm::dvec3 arrowHeadMm_{0.0};  // while an arrow is dragged: its head, and the cursor
  QPointF arrowTail_;
  QPointer<QWidget> textEdit_;
  SegmentationModel* segmentation_ = nullptr;
  SegmentToolModel* segmentTools_ = nullptr;
  int segConnection_ = 0, toolConnection_ = 0;
  QImage segmentOverlay_, previewOverlay_;
  FusionModel* fusion_ = nullptr;
  int fusionConnection_ = 0;
  QImage fusionOverlay_;
  std::optional<PlaneGrid> fusedPlane_;  // what fusionOverlay_ shows
  QString cursorReadout_;
  int docConnection_ = 0, timeConnection_ = 0, crossConnection_ = 0, wlConnection_ = 0,
      stateConnection_ = 0;
  SlabRenderer slabs_;  // last member: its thread stops before the rest goes
};

}  // namespace voxray::ui
