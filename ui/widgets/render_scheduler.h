#pragma once
// Decides when the 3D view needs a frame and how good it must be: any change of the render
// state asks the render thread for a frame; during a drag the frames are cheap (the
// interactive quality preset, its size and step adapted to hold the preferred drag frame
// rate by AdaptiveQuality), and once the mouse has been still for a moment, or is
// released, one frame of the chosen quality follows, in bands of rows (refine_bands.h) each
// shown as it finishes; a camera move abandons the bands left and is rendered next.
// Also measures frames per second for the status bar.
#include <memory>

#include <QElapsedTimer>
#include <QObject>
#include <QSize>
#include <QTimer>

#include "progressive_render.h"
#include "render_state_model.h"
#include "render_worker.h"
#include "segmentation_model.h"
#include "status_text.h"
#include "volume_document.h"

namespace voxray::ui {

class RenderScheduler : public QObject {
  Q_OBJECT
 public:
  // DEVICE: a ClContext selector. The scheduler owns the render thread.
  RenderScheduler(RenderStateModel& state, VolumeDocument& doc, const QString& device,
                  QObject* parent = nullptr);
  ~RenderScheduler() override;

  void setViewSize(QSize size);
  QSize viewSize() const { return viewSize_; }  // what the view's frames are planned for
  // Called by views while the user drags anything that changes the 3D image (camera, clip
  // box, light: cheap frames) and when the drag ends.
  void beginInteraction();
  void endInteraction();
  // The full-quality parameters of the next frame (for overlays and exports).
  RenderParams fullParams() const;
  // The size and step drag frames use now.
  const DragSetting& dragSetting() const { return adaptive_.setting(); }
  // Renders once at SIZE for an export; the result arrives as exportReady.
  void requestExport(QSize size);
  // Renders the view's full-quality frame once more with each pixel's iso hit; the result
  // arrives as pickReady (Frame::hits, the frame's own size).
  void requestPick();
  // The segmentation model changed: the 3D view's copy takes its edits (setSegmentation after
  // a load, updateSegmentation of the edited box after an edit) and a frame follows.
  void updateSegmentation(SegmentationModel& model);
  // Low-priority frames behind the view's (the preset gallery's pictures): each (tag,
  // params) as given, replacing the list not yet rendered; each arrives as backgroundReady.
  void requestBackground(std::vector<std::pair<int, RenderParams>> frames);
  // Fused dvr: OVERLAY (null: none) with its table, raycast with the volume; a frame follows.
  void setOverlay(std::shared_ptr<const Volume> overlay, TransferFunction tf);
  // A frame of VOLUME on the render thread's device, for another thread (the movie export):
  // blocks; throws as RenderWorker::renderOnDevice. Thread-safe.
  Image renderOnDevice(const RenderParams& params, const Volume* volume) {
    return worker_->renderOnDevice(params, volume);
  }
  // Whether a frame of the last change is still to come (RenderWorker::busy).
  bool busy() const { return worker_->busy(); }

 signals:
  void frameReady(std::shared_ptr<const voxray::Frame> frame);
  // A band of the sharp frame before its last (Frame::bandsDone < Frame::bands): the view
  // shows it; frameReady follows with the whole frame unless a new request abandons it.
  void bandReady(std::shared_ptr<const voxray::Frame> frame);
  void exportReady(std::shared_ptr<const voxray::Frame> frame);
  void pickReady(std::shared_ptr<const voxray::Frame> frame);
  void backgroundReady(std::shared_ptr<const voxray::Frame> frame);
  void firstFullFrame();
  void statsChanged(double fps, double lastMs, bool interactive);
  void deviceReady(const QString& name);
  void renderError(const QString& message, bool volumeRejected);
  // Lighting cinematic: "cinematic: 128 samples · 12.3 s", or "" for other lighting.
  void progressChanged(const QString& text);
  // After a volume's first sharp frame the kernels of a drag and of the other modes build in
  // the background (RenderWorker::prepare): LEFT of them still to build, 0 when done.
  void preparingChanged(int left);

 private:
  void requestFrame();
  // The GPU memory budget preference to the worker, when it changed (RenderWorker::setOutOfCore).
  void sendOutOfCore();
  void onFrame(std::shared_ptr<const Frame> frame);
  // The frames likely next: this look's drag frames, the other modes' still and drag frames.
  std::vector<RenderParams> likelyFrames() const;

  RenderStateModel& state_;
  VolumeDocument& doc_;
  std::unique_ptr<RenderWorker> worker_;
  QSize viewSize_{512, 384};
  bool interacting_ = false;
  bool sawFullFrame_ = false;
  QTimer settle_;  // the mouse stopped: time to refine
  QElapsedTimer clock_;
  FrameRateMeter rate_;
  AdaptiveQuality adaptive_;
  ProgressiveRender progressive_;  // cinematic: the next pass while the view is still
  int stateConnection_ = 0, docConnection_ = 0, timeConnection_ = 0;
  int sentBudgetMib_ = -1;         // the budget the worker has (-1: none sent yet)
  bool sentSegmentation_ = false;  // the worker holds a segmentation: edits send their box
};

}  // namespace voxray::ui
